// `raylab render --frames A:B`: an animation along the scene's camera path. Frames are the unit
// of work: in one process they are rendered one after the other; under MPI rank 0 hands them
// out as ranks finish the last (the same coordination over a one-rank channel in one process).

#include <fmt/core.h>

#include <csignal>
#include <optional>

#include "camera_options.h"
#include "raylab/core/error.h"
#include "raylab/core/index_ranges.h"
#include "raylab/core/interrupt.h"
#include "raylab/dist/animation.h"
#include "raylab/dist/frame_range.h"
#include "raylab/dist/process_channel.h"
#include "raylab/io/atomic_file.h"
#include "render_modes.h"
#include "render_report.h"

namespace raylab::cli {
namespace {

// prepare_render, with the first frame's file checked on rank 0 (and every frame's against the
// scene's own files) and a scene without a camera path refused.
std::unique_ptr<RenderSetup> prepare_frames(const RenderArgs& given, bool root, int first, int last) {
  if (root) check_writable(dist::frame_output(given.output, first));
  std::unique_ptr<RenderSetup> prepared = prepare_render(given, false);
  for (int frame = first; root && frame <= last; ++frame) {
    check_not_an_input(dist::frame_output(given.output, frame), prepared->scene.source_files);
  }
  if (prepared->scene.camera_path.empty()) {
    throw UsageError("--frames needs a camera path, and the scene '" + given.scene +
                     "' has none (a scene file's \"camera\": {\"path\": ...}; see docs/scene-format.md)");
  }
  return prepared;
}

// Rank 0's side: writes each frame as it arrives, keeps the bar and the totals.
struct FrameWriter {
  FrameWriter(const RenderArgs& a, int frames) : args(a), total(frames) {}

  const RenderArgs& args;
  int total = 0;
  bool interactive = stderr_interactive();
  std::optional<ProgressBar> bar;
  int written = 0;
  RenderStats totals;

  void write(const dist::RenderedFrame& f) {
    const std::string path = dist::frame_output(args.output, f.frame);
    write_outputs(args, path, f.film, f.result.samples_per_pixel);
    totals += f.result.stats;
    ++written;
    if (bar) bar->update(written, total);
    if (!args.quiet && !interactive) fmt::print(stderr, "frame {}: wrote {}\n", f.frame, path);
  }
};

// Rank 0, after the run over `ranks` ranks: what was written, or why not all of it.
int report_frames(const RenderSetup& setup, const dist::Animation& run, FrameWriter& writer, int first, int last,
                  int ranks) {
  const RenderArgs& args = setup.args;
  const RenderSettings& s = setup.scene.settings;
  const dist::DistributedOutcome outcome = run.result.outcome;
  if (outcome != dist::DistributedOutcome::kComplete) {
    if (writer.bar) writer.bar->finish(outcome == dist::DistributedOutcome::kFailed ? "failed" : "interrupted");
    fmt::print(stderr, "raylab: {} of {} frames written; not rendered: {}\n", writer.written, writer.total,
               index_ranges(run.result.unfinished));
    if (outcome == dist::DistributedOutcome::kFailed) return 1;
    return interrupt_exit_status(interrupt_signal() != 0 ? interrupt_signal() : SIGTERM);
  }
  if (writer.bar) writer.bar->clear();
  if (args.stats) {
    print_stats(writer.totals, setup.accel->info(), run.seconds);
    print_rank_table(run.result.ranks, "frames");
  }
  if (!args.quiet) {
    print_summary(fmt::format("wrote frames {}-{} as {} ({} frames, {}x{}, {} rays, --accel {}, {} rank{})", first,
                              last, dist::frame_output(args.output, first), writer.total, s.width, s.height,
                              writer.totals.total_rays(), args.accel, ranks, ranks > 1 ? "s" : ""),
                  run.seconds);
  }
  return 0;
}

// Every rank's part of frames `first` to `last` over `channel`; rank 0 writes them and reports.
int render_frames(RenderSetup& setup, bool root, dist::Channel& channel, const std::string& host, int first, int last) {
  const RenderArgs& args = setup.args;
  dist::AnimationOptions options;
  options.first = first;
  options.last = last;
  set_rank_options(options, setup, host);
  FrameWriter writer(args, last - first + 1);
  if (root) {
    if (!args.quiet) writer.bar.emplace("frames", stderr, writer.interactive);
    options.on_frame = [&writer](const dist::RenderedFrame& f) { writer.write(f); };
    options.on_stopping = print_stopping;
  }
  const dist::Animation run = dist::render_animation(channel, setup.scene, *setup.accel, options);
  if (!root) return run.exit_status;
  return report_frames(setup, run, writer, first, last, channel.size());
}

}  // namespace

int run_frames(const RenderArgs& given) {
  if (given.passes || given.checkpoint || given.resume) {
    throw UsageError(
        "--frames renders each frame in one go: no --passes, --checkpoint or --resume (frames "
        "already written can be skipped by giving a later --frames range)");
  }
  if (!given.camera.empty()) {
    throw UsageError(std::string("--frames follows the scene's camera path, and the camera flags (") + kCameraFlagList +
                     ") set a still camera: render one view without --frames");
  }
  const auto [first_frame, last_frame] = *dist::parse_frame_range(*given.frames);
  const int first = first_frame, last = last_frame;
  install_interrupt_handlers(end_at_once, true);
  dist::ProcessChannel process;
  dist::Channel& channel = process.channel();
  return prepare_then_render(
      channel, [&](bool root) { return prepare_frames(given, root, first, last); },
      [&](RenderSetup& setup, bool root) { return render_frames(setup, root, channel, process.host(), first, last); });
}

}  // namespace raylab::cli
