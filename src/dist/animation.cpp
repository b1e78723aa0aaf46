#include "raylab/dist/animation.h"

#include <chrono>

#include "raylab/core/interrupt.h"
#include "raylab/core/stopwatch.h"
#include "raylab/dist/rank_failure.h"
#include "raylab/io/atomic_file.h"

namespace raylab::dist {
namespace {

bool interrupted() { return interrupt_signal() != 0; }

FramesOptions frames_options(Scene& scene, const Accelerator& accel, const AnimationOptions& options) {
  FramesOptions f;
  for (int frame = options.first; frame <= options.last; ++frame) f.frames.push_back(frame);
  f.agreement = options.agreement;
  f.threads = render_thread_count(options.render);
  f.rank_timeout_seconds = options.rank_timeout_seconds;
  f.host = options.host;
  f.should_stop = interrupted;
  // One frame at a time per process: the scene's camera is set for the frame, then rendered.
  f.render_frame = [&scene, &accel, &options](int frame) {
    scene.camera = scene.camera_path.at(frame);
    RenderedFrame out;
    out.frame = frame;
    out.film = Film(scene.settings.width, scene.settings.height);
    RenderOptions render_options = options.render;
    render_options.should_stop = interrupted;
    out.result = render(scene, accel, out.film, render_options);
    return out;
  };
  f.on_frame = options.on_frame;
  f.on_stopping = options.on_stopping;
  return f;
}

}  // namespace

Animation render_animation(Channel& channel, Scene& scene, const Accelerator& accel, const AnimationOptions& options) {
  const FramesOptions frames = frames_options(scene, accel, options);
  // From here the first signal stops handing out frames; the frames written stay.
  install_interrupt_handlers(remove_pending_temporary_files, false);
  const auto start = std::chrono::steady_clock::now();
  Animation out;
  try {
    out.result = render_frames_distributed(channel, frames);
  } catch (const std::exception& e) {
    out.exit_status = fail_outside_protocol(channel, e);
    return out;
  }
  out.seconds = seconds_since(start);
  if (channel.rank() != 0 && out.result.outcome != DistributedOutcome::kComplete) {
    out.exit_status = interrupted() ? interrupt_exit_status(interrupt_signal()) : 1;
  }
  return out;
}

}  // namespace raylab::dist
