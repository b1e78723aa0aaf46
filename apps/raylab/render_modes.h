#pragma once
/// \file
/// The ways `raylab render` runs besides one image in one process: one image across the ranks
/// of an MPI job (render_mpi.cpp), and an animation along the scene's camera path, in one process
/// or across ranks (render_frames.cpp). The protocols are in the library (dist/image_on_ranks.h,
/// dist/animation.h); these set them up from the arguments and report.

#include <exception>
#include <memory>
#include <string>

#include "raylab/dist/channel.h"
#include "raylab/dist/rank_failure.h"
#include "raylab/dist/render_agreement.h"
#include "render_setup.h"

namespace raylab::cli {

/// Runs `render(setup, root)` with the setup `prepare(root)` makes on this rank of `channel`
/// (`root`: rank 0). A failure while preparing (a bad argument, a scene that does not load) is
/// outside the protocol: every rank hears of it (dist::fail_outside_protocol).
template <class Prepare, class Render>
int prepare_then_render(dist::Channel& channel, Prepare prepare, Render render) {
  const bool root = channel.rank() == 0;
  std::unique_ptr<RenderSetup> setup;
  try {
    setup = prepare(root);
  } catch (const std::exception& e) {
    return dist::fail_outside_protocol(channel, e);
  }
  return render(*setup, root);
}

/// Sets what every kind of distributed render of `setup` asks of its ranks in `options`
/// (dist::DistributedOptions or dist::AnimationOptions): the render options, the agreement they
/// check, --rank-timeout, and this machine's name `host`.
template <class Options>
void set_rank_options(Options& options, const RenderSetup& setup, const std::string& host) {
  options.render = render_options(setup);
  options.agreement = dist::render_agreement(setup.header);
  options.rank_timeout_seconds = setup.args.rank_timeout;
  options.host = host;
}

/// One image across the ranks of the MPI job this process belongs to; every rank runs this.
int run_under_mpi(const RenderArgs& args);

/// Frames --frames A:B of the scene's camera path, each written as it completes.
int run_frames(const RenderArgs& args);

}  // namespace raylab::cli
