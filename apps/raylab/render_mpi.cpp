// `raylab render` as one rank of an MPI job (mpirun -np N raylab render ...): every rank loads
// the scene and renders tiles; rank 0 hands them out, writes the image, checkpoints, reports.

#include <fmt/core.h>
#include <unistd.h>

#include <csignal>
#include <optional>

#include "raylab/core/error.h"
#include "raylab/core/interrupt.h"
#include "raylab/dist/distributed_render.h"
#include "raylab/dist/launcher.h"
#include "raylab/dist/mpi_channel.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/image_io.h"
#include "raylab/render/adaptive.h"
#include "raylab/render/progress.h"
#include "raylab/render/tile_renderer.h"
#include "render_modes.h"

namespace raylab::cli {

void require_mpi_build() {
  if (!dist::mpi_available()) {
    throw UsageError(
        "this process was started by an MPI launcher, but this raylab was built without MPI "
        "(install libopenmpi-dev and rebuild, or run raylab without mpirun)");
  }
}

int fail_outside_protocol(dist::Channel& channel, const std::exception& e) {
  if (channel.rank() == 0) {
    dist::call_off(channel);
    throw;  // the exception being handled: main() prints it and maps it to the exit code
  }
  dist::report_failure(channel, e.what(), 30.0);
  if (dynamic_cast<const UsageError*>(&e) != nullptr) return 2;
  return dynamic_cast<const InputError*>(&e) != nullptr ? 1 : 3;
}

void print_stopping(const std::string& message) {
  fmt::print(stderr, "\nraylab: {}\n", message);
  std::fflush(stderr);
}

void print_rank_table(const std::vector<dist::RankReport>& ranks, const char* unit) {
  fmt::print("{:<6}{:<16}{:>8}{:>8}{:>14}{:>10}{:>10}{:>10}\n", "rank", "host", "threads", unit, "rays", "busy s",
             "wall s", "Mrays/s");
  for (const dist::RankReport& r : ranks) {
    const double mrays = r.wall_seconds > 0 ? r.stats.total_rays() / r.wall_seconds * 1e-6 : 0.0;
    fmt::print("{:<6}{:<16}{:>8}{:>8}{:>14}{:>10.2f}{:>10.2f}{:>10.2f}\n", r.rank, r.host, r.threads, r.jobs,
               r.stats.total_rays(), r.busy_seconds, r.wall_seconds, mrays);
  }
  fmt::print("load imbalance            {:.3f} (busiest rank's busy time over the mean; 1 = balanced)\n",
             dist::load_imbalance(ranks));
}

int run_under_mpi(const RenderArgs& given) {
  require_mpi_build();
  if (given.spd_protocol) throw UsageError("--spd-protocol renders in one process: run it without mpirun");
  // Until the render starts there is nothing to save: a signal ends the run at once.
  install_interrupt_handlers(remove_pending_temporary_files, true);
  dist::MpiSession session;
  dist::Channel& channel = session.channel();
  const bool root = channel.rank() == 0;
  std::unique_ptr<RenderSetup> prepared;
  try {
    prepared = prepare_render(given, root);
    if (is_adaptive_sampler(prepared->sampler)) {
      throw UsageError("the " + prepared->sampler +
                       " sampler refines the whole image at once and cannot be split across MPI ranks; use a "
                       "uniform sampler, or --frames to give each rank whole frames");
    }
  } catch (const std::exception& e) {
    return fail_outside_protocol(channel, e);
  }
  RenderSetup& setup = *prepared;
  const RenderArgs& args = setup.args;
  const RenderSettings& s = setup.scene.settings;

  dist::DistributedOptions options;
  options.render = render_options(setup);
  options.agreement = render_agreement(setup);
  options.rank_timeout_seconds = args.rank_timeout;
  options.host = session.host();
  options.render.should_stop = [] { return interrupt_signal() != 0; };
  TileRenderer renderer(setup.scene, *setup.accel, options.render);
  Film film(root ? s.width : 0, root ? s.height : 0);
  const bool interactive = ::isatty(STDERR_FILENO) != 0;
  std::optional<ProgressBar> bar;
  if (root) {
    if (!args.quiet) bar.emplace("render", stderr, interactive);
    if (bar) options.render.on_progress = [&bar](int done, int total) { bar->update(done, total); };
    options.render.progress = &setup.progress;
    options.render.on_pass = [&](int done, const Film& image) {
      write_image(image, args.output);
      if (!args.quiet) {
        fmt::print(stderr, "{}pass {}/{}: wrote {}\n", interactive ? "\n" : "", done, options.render.passes,
                   args.output);
      }
    };
    // A run that ends early always leaves a checkpoint, as an interrupted local render does.
    if (!options.render.on_checkpoint) {
      options.render.on_checkpoint = [&setup](const RenderProgress& state) {
        RenderCheckpoint checkpoint = setup.header;
        checkpoint.progress = state;
        write_checkpoint(setup.checkpoint_path, checkpoint);
      };
    }
    options.on_stopping = print_stopping;
  }
  // From here the first signal stops handing out tiles and saves what is done.
  install_interrupt_handlers(remove_pending_temporary_files, false);
  dist::DistributedResult result;
  try {
    result = dist::render_distributed(channel, renderer, film, options);
  } catch (const std::exception& e) {
    // Not a rank's failure the protocol reports (those end the run in order): a bug or a
    // resource running out here. The others must not wait for this rank until they time out.
    return fail_outside_protocol(channel, e);
  }
  if (!root) {
    if (result.outcome == dist::DistributedOutcome::kComplete) return 0;
    const int signal = interrupt_signal();
    return signal != 0 ? interrupt_exit_status(signal) : 1;
  }
  if (result.outcome != dist::DistributedOutcome::kComplete) {
    // Saved once already as the run ended; again now that rank 0's own last tiles are in.
    options.render.on_checkpoint(setup.progress);
  }
  if (result.outcome == dist::DistributedOutcome::kFailed) {
    if (bar) bar->finish("failed");
    fmt::print(stderr,
               "raylab: no image written; the finished tiles are saved in {}: fix the cause and resume with the "
               "same command and --resume {}\n",
               setup.checkpoint_path, setup.checkpoint_path);
    return 1;
  }
  if (result.outcome == dist::DistributedOutcome::kInterrupted) {
    const int signal = interrupt_signal() != 0 ? interrupt_signal() : SIGTERM;
    if (bar) bar->finish("interrupted");
    write_outputs(args, args.output, film, result.render.samples_per_pixel);
    print_interrupted(signal, args.output, setup.checkpoint_path, setup.progress);
    return interrupt_exit_status(signal);
  }
  const RenderResult& r = result.render;
  const std::string sampling = sampling_summary(setup, r);
  const double mrays = r.seconds > 0 ? r.stats.total_rays() / r.seconds * 1e-6 : 0.0;
  if (bar) {
    bar->finish(fmt::format("{}x{}, {}, {} rays ({:.2f} Mrays/s), {} ranks", s.width, s.height, sampling,
                            r.stats.total_rays(), mrays, channel.size()));
  }
  print_warnings(r);
  write_outputs(args, args.output, film, r.samples_per_pixel);
  remove_finished_checkpoint(setup);
  if (args.stats) {
    print_stats(r.stats, setup.accel->info(), r.seconds);
    print_rank_table(result.ranks, "tiles");
  }
  if (!args.quiet) {
    fmt::print("wrote {} ({}x{}, {}, {} primary rays, --accel {}, {} ranks) in {}\n", args.output, s.width, s.height,
               sampling, r.primary_rays(), args.accel, channel.size(), ProgressBar::format_duration(r.seconds));
  }
  return 0;
}

}  // namespace raylab::cli
