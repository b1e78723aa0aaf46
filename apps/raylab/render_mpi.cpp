// `raylab render` as one rank of an MPI job (mpirun -np N raylab render ...): every rank loads
// the scene and renders tiles; rank 0 hands them out, writes the image, checkpoints, reports.

#include <fmt/core.h>

#include <csignal>
#include <optional>

#include "raylab/core/error.h"
#include "raylab/core/interrupt.h"
#include "raylab/dist/image_on_ranks.h"
#include "raylab/dist/launcher.h"
#include "raylab/dist/mpi_channel.h"
#include "raylab/io/atomic_file.h"
#include "raylab/render/adaptive.h"
#include "render_modes.h"
#include "render_report.h"

namespace raylab::cli {
namespace {

// prepare_render, and the samplers that cannot be split across ranks refused.
std::unique_ptr<RenderSetup> prepare_on_ranks(const RenderArgs& given, bool root) {
  std::unique_ptr<RenderSetup> prepared = prepare_render(given, root);
  if (is_adaptive_sampler(prepared->sampler)) {
    throw UsageError("the " + prepared->sampler +
                     " sampler refines the whole image at once and cannot be split across MPI ranks; use a "
                     "uniform sampler, or --frames to give each rank whole frames");
  }
  return prepared;
}

// The options of every rank; on rank 0 also the progress bar, the image after each pass and the
// checkpoints.
dist::DistributedOptions distributed_options(RenderSetup& setup, bool root, const std::string& host,
                                             std::optional<ProgressBar>& bar) {
  dist::DistributedOptions options;
  set_rank_options(options, setup, host);
  if (!root) return options;
  show_progress(setup.args, options.render, bar);
  options.render.progress = &setup.progress;
  write_each_pass(setup, options.render);
  // A run that ends early always leaves a checkpoint, as an interrupted local render does.
  if (!options.render.on_checkpoint) {
    options.render.on_checkpoint = [&setup](const RenderProgress& state) {
      RenderCheckpoint checkpoint = setup.header;
      checkpoint.progress = state;
      write_checkpoint(setup.checkpoint_path, checkpoint);
    };
  }
  options.on_stopping = print_stopping;
  return options;
}

// Every rank's part of the image over `channel`; rank 0 writes it and reports.
int render_image(RenderSetup& setup, bool root, dist::Channel& channel, const std::string& host) {
  std::optional<ProgressBar> bar;
  const dist::DistributedOptions options = distributed_options(setup, root, host, bar);
  const dist::ImageOnRanks run = dist::render_image_on_ranks(channel, setup.scene, *setup.accel, options);
  if (!root) return run.exit_status;
  if (run.result.outcome == dist::DistributedOutcome::kFailed) {
    if (bar) bar->finish("failed");
    fmt::print(stderr,
               "raylab: no image written; the finished tiles are saved in {}: fix the cause and resume with the "
               "same command and --resume {}\n",
               setup.checkpoint_path, setup.checkpoint_path);
    return 1;
  }
  if (run.result.outcome == dist::DistributedOutcome::kInterrupted) {
    const int signal = interrupt_signal() != 0 ? interrupt_signal() : SIGTERM;
    return report_interrupted(setup, run.film, run.result.render, bar, signal, false);
  }
  return report_finished(setup, run.film, run.result.render, bar, &run.result.ranks, channel.size());
}

}  // namespace

int run_under_mpi(const RenderArgs& given) {
  dist::require_mpi_build();
  if (given.spd_protocol) throw UsageError("--spd-protocol renders in one process: run it without mpirun");
  // Until the render starts there is nothing to save: a signal ends the run at once.
  install_interrupt_handlers(end_at_once, true);
  dist::MpiSession session;
  dist::Channel& channel = session.channel();
  return prepare_then_render(
      channel, [&](bool root) { return prepare_on_ranks(given, root); },
      [&](RenderSetup& setup, bool root) { return render_image(setup, root, channel, session.host()); });
}

}  // namespace raylab::cli
