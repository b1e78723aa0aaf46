#pragma once
/// \file
/// An animation along a scene's camera path as a program running on each rank of a job (or
/// alone, over a one-rank channel) renders it: around render_frames_distributed, each frame's
/// camera and render, the interrupt handling and the errors outside the protocol
/// (fail_outside_protocol). The program writes each frame as rank 0 receives it.

#include <cstdint>
#include <functional>
#include <string>

#include "raylab/accel/accelerator.h"
#include "raylab/dist/channel.h"
#include "raylab/dist/distributed_frames.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/scene.h"

namespace raylab::dist {

/// What render_animation needs besides the scene.
struct AnimationOptions {
  int first = 0;  ///< the first frame (an index into the scene's camera path)
  int last = 0;   ///< the last frame, inclusive
  /// Each frame's render (threads, packets, statistics); should_stop is set to the interrupt.
  RenderOptions render;
  std::uint64_t agreement = 0;       ///< as DistributedOptions::agreement
  double rank_timeout_seconds = 60;  ///< as DistributedOptions::rank_timeout_seconds
  std::string host;                  ///< this machine's name
  /// Rank 0: each rendered frame, in the order they finish (as FramesOptions::on_frame).
  std::function<void(const RenderedFrame&)> on_frame;
  /// Rank 0: the message when the run ends early (as FramesOptions::on_stopping). May be empty.
  std::function<void(const std::string&)> on_stopping;
};

/// What render_animation returns.
struct Animation {
  FramesResult result;  ///< as render_frames_distributed returns it
  double seconds = 0;   ///< wall time of the frames, from the first handed out to the last in
  /// The exit status for this process on a rank other than 0: 0 when complete, the interrupt's
  /// (interrupt_exit_status), 1 when the run failed, or fail_outside_protocol's. Rank 0: 0 (it
  /// reports from result.outcome).
  int exit_status = 0;
};

/// Renders frames options.first to options.last of `scene`'s camera path (which must hold them)
/// across the ranks of `channel`: each frame sets scene.camera, then renders with all this
/// process's threads. Every rank calls this with a scene and settings alike. Installs the
/// interrupt handlers so that the first signal stops handing out frames (the frames delivered
/// stay). An exception out of the protocol goes through fail_outside_protocol (on rank 0 it is
/// rethrown).
Animation render_animation(Channel& channel, Scene& scene, const Accelerator& accel, const AnimationOptions& options);

}  // namespace raylab::dist
