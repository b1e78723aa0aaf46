#pragma once
/// \file
/// The ways `raylab render` runs besides one image in one process: one image across the ranks
/// of an MPI job (render_mpi.cpp), and an animation along the scene's camera path, in one process
/// or across ranks (render_frames.cpp). The protocols are in the library (dist/image_on_ranks.h,
/// dist/animation.h); these set them up from the arguments and report.

#include "render_setup.h"

namespace raylab::cli {

/// One image across the ranks of the MPI job this process belongs to; every rank runs this.
int run_under_mpi(const RenderArgs& args);

/// Frames --frames A:B of the scene's camera path, each written as it completes.
int run_frames(const RenderArgs& args);

}  // namespace raylab::cli
