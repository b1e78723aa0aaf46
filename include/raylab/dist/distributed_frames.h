#pragma once
/// \file
/// An animation rendered across the ranks of a job: rank 0 hands out whole frames as ranks ask
/// for them (rank 0 renders frames too), each rank renders a frame with all its threads, and
/// rank 0 receives every frame's image and hands it to the caller (who writes it) as it arrives.
/// Faults end the run as for one image (distributed_render.h): the frames written so far stay,
/// the message names the rank and the frame it held.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "raylab/dist/channel.h"
#include "raylab/dist/distributed_render.h"
#include "raylab/render/film.h"
#include "raylab/render/renderer.h"

namespace raylab::dist {

/// One frame of an animation, rendered.
struct RenderedFrame {
  int frame = 0;        ///< its number
  Film film{0, 0};      ///< its image
  RenderResult result;  ///< what its render reported
};

/// What render_frames_distributed needs.
struct FramesOptions {
  std::vector<int> frames;  ///< the frames to render, handed out in this order
  /// Renders one frame with this process's threads. Every rank calls it, from a thread of its own.
  std::function<RenderedFrame(int)> render_frame;
  /// Rank 0: each rendered frame, from the calling thread, in the order they finish.
  std::function<void(const RenderedFrame&)> on_frame;
  /// Asked between messages on every rank: an interrupt. May be empty.
  std::function<bool()> should_stop;
  /// Rank 0: the message when the run ends early, as soon as it is known. May be empty.
  std::function<void(const std::string&)> on_stopping;
  int threads = 1;                       ///< threads render_frame uses (for the report)
  std::uint64_t agreement = 0;           ///< as DistributedOptions::agreement
  double rank_timeout_seconds = 60;      ///< as DistributedOptions::rank_timeout_seconds
  double interrupt_grace_seconds = 0.5;  ///< as DistributedOptions::interrupt_grace_seconds
  std::string host;                      ///< this machine's name
};

/// How a distributed animation ended.
struct FramesResult {
  DistributedOutcome outcome = DistributedOutcome::kComplete;
  std::vector<RankReport> ranks;  ///< rank 0: per rank, `jobs` counting frames
  std::vector<int> unfinished;    ///< rank 0: frames not delivered (empty when complete)
  std::string message;            ///< rank 0, when not complete: what happened
};

/// Renders options.frames across the ranks of `channel` (see the file comment); every rank calls it.
FramesResult render_frames_distributed(Channel& channel, const FramesOptions& options);

}  // namespace raylab::dist
