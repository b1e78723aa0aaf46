#pragma once
/// \file
/// One image rendered by several processes (ranks). Rank 0 coordinates: it hands out tiles one at
/// a time as ranks ask for them (a rank asks for the next when it finishes one, so fast and slow
/// ranks balance), renders tiles itself while it waits, gathers the sums and develops the image.
/// Every rank loads the scene and builds its own accelerator; a hello message checks that all
/// of them render the same thing. The image has the bits of a render in one process: each tile's
/// samples are seeded by pixel and index, and the sums are added in the same order wherever the
/// tile is rendered (TileRenderer).
///
/// Faults: a rank that reports an error, presents another scene, or falls silent while holding
/// tiles ends the run with a message naming it and the tiles it held; no image is written from
/// such a run, and the finished tiles go to a checkpoint so that the run can be resumed.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "raylab/core/stats.h"
#include "raylab/dist/channel.h"
#include "raylab/render/film.h"
#include "raylab/render/renderer.h"
#include "raylab/render/tile_renderer.h"

namespace raylab::dist {

/// What a distributed render needs besides the scene (see the file comment).
struct DistributedOptions {
  /// Rank 0 uses `passes`, `progress` (a state to go on from, and where the state is kept),
  /// `on_progress`, `on_pass`, `on_checkpoint` and `checkpoint_seconds` as render() does; every
  /// rank asks `should_stop` (an interrupt) between messages.
  RenderOptions render;
  /// A hash of everything that decides the image (the scene as loaded, the settings); every rank
  /// must present rank 0's, or the run fails before any tile is exchanged.
  std::uint64_t agreement = 0;
  /// A rank that holds tiles and has sent nothing for this long is taken for dead (seconds).
  /// Ranks send a heartbeat every second, so only a hung or dead process stays silent.
  double rank_timeout_seconds = 60.0;
  /// After an interrupt, how long rank 0 waits for the other ranks to say they were interrupted
  /// too (a launcher stopping the job signals every rank) and for results already on their way.
  double interrupt_grace_seconds = 0.5;
  /// This machine's name, for the per-rank report.
  std::string host;
  /// Rank 0: called once when the run is ending early, before any waiting for the threads, with
  /// the message for the user (an interrupt, or a failure naming the rank and its tiles), so that
  /// it is out even if the launcher kills the process soon after. May be empty.
  std::function<void(const std::string&)> on_stopping;
};

/// What one rank did.
struct RankReport {
  int rank = 0;             ///< the rank
  std::string host;         ///< its machine
  int threads = 0;          ///< its render threads
  int jobs = 0;             ///< tiles (one pass of one tile each) or, in frames mode, frames it rendered
  RenderStats stats;        ///< its rays and traversal counts
  double busy_seconds = 0;  ///< thread-seconds spent rendering jobs
  double wall_seconds = 0;  ///< from its start to its end
};

/// How a distributed render ended.
enum class DistributedOutcome {
  kComplete,     ///< every pass of every tile is in
  kInterrupted,  ///< an interrupt (should_stop) ended it; the progress holds the finished tiles
  kFailed,       ///< a rank failed (see DistributedResult::message)
};

/// What render_distributed returns.
struct DistributedResult {
  DistributedOutcome outcome = DistributedOutcome::kComplete;
  /// Rank 0: the render as render() reports it (statistics summed over every rank, wall time,
  /// samples per pixel, notices). Other ranks: their own statistics.
  RenderResult render;
  /// Rank 0: one report per rank that sent one, in rank order (rank 0's included).
  std::vector<RankReport> ranks;
  /// Rank 0, when not complete: what happened, for the user (names ranks and tiles).
  std::string message;
};

/// Renders the image of `renderer`'s scene across the ranks of `channel`. On rank 0 the image
/// goes into `film` (developed from options.render.progress, or from its own state); other ranks
/// leave `film` untouched (it may be empty). Every rank must call this with a renderer for the
/// same scene and settings.
DistributedResult render_distributed(Channel& channel, TileRenderer& renderer, Film& film,
                                     const DistributedOptions& options);

/// Rank 0, failing before render_distributed (its scene did not load): tells every other rank
/// that the run is off, so that none waits for work that will not come.
void call_off(Channel& channel);

/// Any other rank, failing before render_distributed: tells rank 0 why (rank 0 names the rank
/// and the reason), then waits at most `seconds` for rank 0 to call the run off.
void report_failure(Channel& channel, const std::string& message, double seconds);

/// The load imbalance of `ranks`: the busiest rank's busy time over the mean busy time (1 is
/// perfect balance; 0 when nothing was busy).
double load_imbalance(const std::vector<RankReport>& ranks);

}  // namespace raylab::dist
