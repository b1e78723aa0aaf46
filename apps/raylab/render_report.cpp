#include "render_report.h"

#include <fmt/core.h>

#include <csignal>
#include <filesystem>

#include "raylab/core/byte_size.h"
#include "raylab/core/index_ranges.h"
#include "raylab/core/interrupt.h"
#include "raylab/io/partial_image.h"
#include "raylab/render/adaptive.h"

namespace raylab::cli {
namespace {

// The unfinished tiles as ranges, cut after about a line: the tiles start in a scattered order,
// so an interrupted render's unfinished ones are many short ranges (all of them are in the checkpoint).
std::string unfinished_list(const std::vector<int>& unfinished) {
  constexpr std::size_t kMost = 160;
  std::string list = index_ranges(unfinished);
  if (list.size() <= kMost) return list;
  list.resize(list.rfind(", ", kMost));
  return list + ", ...";
}

// Tells the user what an interrupted render wrote and how to go on. `partial`: where the
// partial image went; beside `output` when that held an image of the user's, which is kept.
void print_interrupted(int signal, const std::string& output, const std::string& partial,
                       const std::string& checkpoint_path, const RenderProgress& p) {
  const std::vector<int> unfinished = p.unfinished_tiles();
  fmt::print(stderr, "raylab: interrupted by {}: wrote the partial image {} and the checkpoint {}\n",
             signal == SIGTERM ? "SIGTERM" : "SIGINT", partial, checkpoint_path);
  if (partial != output) fmt::print(stderr, "  {} was there before this render and is left as it was\n", output);
  fmt::print(stderr,
             "  pass {} of {}: {} of {} tiles unfinished{}: {}\n"
             "  resume with the same command and --resume {}\n",
             p.passes_done + 1, p.passes, unfinished.size(), p.tile_count(),
             p.passes_done == 0 ? " (black in the image)" : "", unfinished_list(unfinished), checkpoint_path);
}

// Prints a finished render's notices and its non-finite sample warning.
void print_warnings(const RenderResult& result) {
  for (const std::string& n : result.notices) fmt::print(stderr, "note: {}\n", n);
  if (result.stats.nonfinite_samples > 0) {
    fmt::print(stderr, "warning: {} samples had NaN or infinite radiance and were replaced by black\n",
               result.stats.nonfinite_samples);
  }
}

// Removes the checkpoint of a render that has completed (when it saved checkpoints).
void remove_finished_checkpoint(const RenderSetup& setup) {
  // The image is whole: a checkpoint of this render is of no more use.
  std::error_code removed;
  if (saves_checkpoints(setup.args) && std::filesystem::remove(setup.checkpoint_path, removed) && !setup.args.quiet) {
    fmt::print(stderr, "note: removed the checkpoint {} (the render is complete)\n", setup.checkpoint_path);
  }
}

// Removes what an interrupted run of this render left beside the output, now that the render
// is complete: its partial image (a file of this name is no one else's).
void remove_stale_partial_image(const RenderSetup& setup) {
  const std::string partial = partial_image_beside(setup.args.output);
  std::error_code removed;
  if (std::filesystem::remove(partial, removed) && !setup.args.quiet) {
    fmt::print(stderr, "note: removed the partial image {} (the render is complete)\n", partial);
  }
}

// The one-line description of the sampling for the summary ("16 spp jittered").
std::string sampling_summary(const RenderSetup& setup, const RenderResult& result) {
  const RenderSettings& s = setup.scene.settings;
  const double pixels = static_cast<double>(s.width) * s.height;
  if (is_adaptive_sampler(setup.sampler)) {
    return fmt::format("{}, {:.2f} primary rays per pixel", setup.sampler,
                       static_cast<double>(result.primary_rays()) / pixels);
  }
  return fmt::format("{} spp {}", result.samples_per_pixel.empty() ? s.spp : int(result.samples_per_pixel[0]),
                     setup.sampler);
}

}  // namespace

void print_stats(const RenderStats& s, const AccelInfo& info, double seconds) {
  fmt::print("{:<12}{:>14}{:>14}\n", "rays", "cast", "hit");
  for (int k = 0; k < static_cast<int>(RayKind::kCount); ++k) {
    fmt::print("{:<12}{:>14}{:>14}\n", ray_kind_name(static_cast<RayKind>(k)), s.rays[k], s.ray_hits[k]);
  }
  std::uint64_t hits = 0;
  for (auto h : s.ray_hits) hits += h;
  const double total = static_cast<double>(s.total_rays());
  fmt::print("{:<12}{:>14}{:>14}\n", "total", s.total_rays(), hits);
  fmt::print("non-finite samples        {} (NaN or infinite radiance, replaced by black)\n", s.nonfinite_samples);
  fmt::print("total internal reflections {} (reflection ray only)\n", s.total_internal_reflections);
  fmt::print("nodes visited per ray     {:.2f}\n", total > 0 ? s.traversal.nodes_visited / total : 0.0);
  fmt::print("primitive tests per ray   {:.2f}\n", total > 0 ? s.traversal.prim_tests / total : 0.0);
  if (s.traversal.volume_tests > 0) {
    fmt::print("wrapper tests per ray     {:.2f}\n", total > 0 ? s.traversal.volume_tests / total : 0.0);
  }
  fmt::print("accelerator               {} ({} primitives, {} nodes, {} leaves, depth {})\n", info.name,
             info.primitive_count, info.node_count, info.leaf_count, info.max_depth);
  fmt::print("build time                {:.2f} ms\n", info.build_seconds * 1e3);
  fmt::print("accelerator memory        {} ({:.1f} bytes per primitive)\n", human_bytes(info.memory_bytes),
             info.primitive_count ? static_cast<double>(info.memory_bytes) / info.primitive_count : 0.0);
  fmt::print("render time               {:.3f} s (with counting enabled)\n", seconds);
  fmt::print("throughput                {:.2f} Mrays/s\n", seconds > 0 ? total / seconds * 1e-6 : 0.0);
}

void print_summary(const std::string& what, double seconds) {
  fmt::print(stderr, "{} in {}\n", what, ProgressBar::format_duration(seconds));
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

int report_finished(const RenderSetup& setup, const Film& film, const RenderResult& result,
                    std::optional<ProgressBar>& bar, const std::vector<dist::RankReport>* ranks, int rank_count) {
  const RenderArgs& args = setup.args;
  const RenderSettings& s = setup.scene.settings;
  const std::string sampling = sampling_summary(setup, result);
  const double mrays = result.seconds > 0 ? result.stats.total_rays() / result.seconds * 1e-6 : 0.0;
  const std::string on_ranks = ranks ? fmt::format(", {} ranks", rank_count) : "";
  if (bar) bar->clear();
  print_warnings(result);
  write_outputs(args, args.output, film, result.samples_per_pixel);
  remove_finished_checkpoint(setup);
  remove_stale_partial_image(setup);
  if (args.stats) {
    print_stats(result.stats, setup.accel->info(), result.seconds);
    if (ranks) print_rank_table(*ranks, "tiles");
  }
  // The one line of a successful render, on stderr with the other reports: stdout stays for
  // what scripts read (--stats, --json -).
  if (!args.quiet) {
    print_summary(fmt::format("wrote {} ({}x{}, {}, {} rays at {:.2f} Mrays/s, --accel {}{})", args.output, s.width,
                              s.height, sampling, result.stats.total_rays(), mrays, args.accel, on_ranks),
                  result.seconds);
  }
  return 0;
}

int report_interrupted(RenderSetup& setup, const Film& film, const RenderResult& result,
                       std::optional<ProgressBar>& bar, int signal, bool save_checkpoint) {
  const RenderArgs& args = setup.args;
  if (bar) bar->finish("interrupted");
  const std::string partial = partial_image_path(args.output, setup.output_existed, setup.output_written);
  write_outputs(args, partial, film, result.samples_per_pixel);
  if (save_checkpoint) {
    RenderCheckpoint checkpoint = setup.header;
    checkpoint.progress = std::move(setup.progress);
    write_checkpoint(setup.checkpoint_path, checkpoint);
    setup.progress = std::move(checkpoint.progress);
  }
  print_interrupted(signal, args.output, partial, setup.checkpoint_path, setup.progress);
  return interrupt_exit_status(signal);
}

}  // namespace raylab::cli
