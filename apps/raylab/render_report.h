#pragma once
/// \file
/// What `raylab render` tells the user after the pixels, in one process, across MPI ranks and for
/// animations: the summary, the warnings, --stats, and what an interrupted or failed run left.

#include <optional>
#include <string>
#include <vector>

#include "raylab/dist/distributed_render.h"
#include "raylab/render/progress.h"
#include "render_setup.h"

namespace raylab::cli {

/// Prints ray counts, traversal work, the accelerator and timings (--stats).
void print_stats(const RenderStats& stats, const AccelInfo& info, double seconds);

/// Prints the per-rank table of --stats under MPI (`unit`: what a rank's jobs are, "tiles" or
/// "frames") and the load imbalance.
void print_rank_table(const std::vector<dist::RankReport>& ranks, const char* unit);

/// Prints the one line of a successful render on stderr: `what` (which names what was written)
/// and the time the pixels took, `seconds` (not with --quiet: the caller decides).
void print_summary(const std::string& what, double seconds);

/// Rank 0: prints at once why a distributed run is ending early (before any waiting, in case the
/// launcher kills the process soon after).
void print_stopping(const std::string& message);

/// A render that completed: clears `bar`, prints the notices and warnings, writes the outputs
/// from `film`, removes the checkpoint and a partial image an earlier interrupted run left beside
/// the output, prints --stats and the one summary line (print_summary). `ranks`: under MPI, the
/// per-rank reports of the `rank_count` ranks (the summary then counts them), else null. Returns
/// the exit status, 0.
int report_finished(const RenderSetup& setup, const Film& film, const RenderResult& result,
                    std::optional<ProgressBar>& bar, const std::vector<dist::RankReport>* ranks, int rank_count);

/// A render interrupted by `signal`: finishes `bar`, writes the partial image from `film` (at the
/// output, or beside it when the output held an image of the user's: partial_image_path), saves
/// the checkpoint of setup.progress when `save_checkpoint` (else it is saved already), and tells
/// the user how to go on. Returns the exit status for the signal.
int report_interrupted(RenderSetup& setup, const Film& film, const RenderResult& result,
                       std::optional<ProgressBar>& bar, int signal, bool save_checkpoint);

}  // namespace raylab::cli
