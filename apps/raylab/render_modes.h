#pragma once
/// \file
/// The ways `raylab render` runs besides one image in one process: one image across the ranks
/// of an MPI job (render_mpi.cpp), and an animation along the scene's camera path, in one process
/// or across ranks (render_frames.cpp).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "raylab/dist/distributed_render.h"
#include "render_setup.h"

namespace raylab::cli {

/// One image across the ranks of the MPI job this process belongs to; every rank runs this.
int run_under_mpi(const RenderArgs& args);

/// Throws UsageError when this build has no MPI (for a process an MPI launcher started).
void require_mpi_build();

/// Ends a run for an error outside the distributed protocol (before the render, or an exception
/// out of it); call it from the catch block. Rank 0 calls the run off and rethrows (main() prints
/// the error and maps it to the exit code); another rank tells rank 0, which names it, and
/// returns its exit code without a message (2 usage, 1 input, 3 anything else).
int fail_outside_protocol(dist::Channel& channel, const std::exception& e);

/// Rank 0: prints at once why a distributed run is ending early (before any waiting, in case the
/// launcher kills the process soon after).
void print_stopping(const std::string& message);

/// Prints the per-rank table of --stats under MPI (`unit`: what a rank's jobs are, "tiles" or
/// "frames") and the load imbalance.
void print_rank_table(const std::vector<dist::RankReport>& ranks, const char* unit);

/// Frames --frames A:B of the scene's camera path, each written as it completes.
int run_frames(const RenderArgs& args);

/// The frames of "A:B" (A to B inclusive) or "A"; nullopt when the text is not one.
std::optional<std::pair<int, int>> parse_frame_range(const std::string& text);

/// OUTPUT for frame `frame`: a run of '#' in the name replaced by the zero-padded number
/// ("f.####.png" -> "f.0007.png"), else the number (4 digits) before the extension
/// ("out.png" -> "out.0007.png").
std::string frame_output(const std::string& output, int frame);

}  // namespace raylab::cli
