// `raylab bench`: argument parsing, file reading and writing, printing; the measuring is in the
// library (lab/bench.h), the ray and hit files in io/ray_file.h.

#include <fmt/core.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "accel_options.h"
#include "command_setup.h"
#include "commands.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/ray_file.h"
#include "raylab/io/scene_loader.h"
#include "raylab/lab/bench.h"

namespace raylab::cli {
namespace {

// Exit code when ours and Embree disagree on some ray (as `compare`).
constexpr int kDisagreementExit = kExitDisagreement;

struct BenchArgs {
  std::string scene;
  std::string rays = "all";
  std::string against = "embree";
  std::string accel = "bvh";
  int threads = 0;
  int repeats = 5;
  int width = 1024;
  int height = 768;
  std::string rays_file, rays_out, hits_out, json;
  bool spatial_splits = false;
  std::string embree_isa = "best";
  bool allow_outside_paths = false;
  bool quiet = false;
};

std::vector<BenchRayKind> kinds_of(const std::string& name) {
  if (name == "primary") return {BenchRayKind::kPrimary};
  if (name == "shadow") return {BenchRayKind::kShadow};
  if (name == "diffuse") return {BenchRayKind::kDiffuse};
  return {BenchRayKind::kPrimary, BenchRayKind::kShadow, BenchRayKind::kDiffuse};
}

int run(const BenchArgs& args) {
  const bool json_stdout = args.json == "-";
  for (const std::string* path : {&args.rays_out, &args.hits_out, &args.json}) {
    if (!path->empty() && *path != "-") check_writable(*path);  // fail before the work, not after it
  }
  BenchOptions options;
  options.kinds = kinds_of(args.rays);
  options.threads = args.threads;
  options.repeats = args.repeats;
  options.width = args.width;
  options.height = args.height;
  options.against_embree = args.against == "embree";
  options.accel = args.accel;
  options.accel_config.bvh.spatial_splits = args.spatial_splits;
  if (args.embree_isa != "best") options.embree_isa = args.embree_isa;
  if (!args.quiet) options.on_progress = [](const std::string& line) { fmt::print(stderr, "bench: {}\n", line); };
  if (!args.rays_file.empty()) {
    options.use_file_rays = true;
    options.file_rays = read_rays(args.rays_file);
    options.file_rays_name = args.rays_file;
  }
  LoadOptions load;
  load.allow_outside_paths = args.allow_outside_paths;
  const Scene scene = load_scene(args.scene, load);
  check_not_inputs(scene, {&args.rays_out, &args.hits_out, &args.json});
  for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);

  BenchReport report;
  try {
    report = run_bench(scene, options);
  } catch (const BenchDisagreement& e) {
    fmt::print(stderr, "raylab: bench FAILED: {}\n", e.what());
    return kDisagreementExit;
  }
  // With the JSON on stdout the table goes to stderr, so that stdout stays one JSON document.
  std::FILE* table = json_stdout ? stderr : stdout;
  fmt::print(table, "{}", format_bench_table(report, args.scene));
  std::fflush(table);
  if (json_stdout) {
    fmt::print("{}", format_bench_json(report, args.scene));
  } else if (!args.json.empty()) {
    write_text_atomically(args.json, format_bench_json(report, args.scene));
  }
  if (!args.rays_out.empty()) write_rays(args.rays_out, report.last_rays);
  if (!args.hits_out.empty()) {
    std::vector<HitRecord> records;
    records.reserve(report.last_hits.size());
    for (const Hit& h : report.last_hits) records.push_back(hit_record(h));
    write_hits(args.hits_out, records);
  }
  if (!args.quiet) {
    for (const std::string* path : {&args.rays_out, &args.hits_out, &args.json}) {
      if (!path->empty() && *path != "-") fmt::print(stderr, "wrote {} ({} rays)\n", *path, report.last_set);
    }
  }
  return 0;
}

void add_options(CLI::App& cmd, BenchArgs& args) {
  cmd.option_defaults()->group("Measurement");
  add_scene_argument(cmd, args.scene);
  CLI::Option* rays = cmd.add_option("--rays", args.rays, "Ray kinds to trace")
                          ->check(CLI::IsMember({"primary", "shadow", "diffuse", "all"}))
                          ->capture_default_str();
  add_threads_option(cmd, args.threads, "Threads for both sides (builds and tracing); 0 = all cores");
  cmd.add_option("--against", args.against, "Reference tracer: embree, or none for our figures only")
      ->check(CLI::IsMember({"embree", "none"}))
      ->capture_default_str();
  cmd.add_option("--repeats", args.repeats, "Timed runs of each figure; the median is reported")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd.add_option("--width", args.width, "Primary rays per row")->check(CLI::Range(1, 16384))->capture_default_str();
  cmd.add_option("--height", args.height, "Rows of primary rays")->check(CLI::Range(1, 16384))->capture_default_str();
  cmd.add_option("--accel", args.accel, "Our acceleration structure")
      ->check(CLI::IsMember(accelerator_choices()))
      ->capture_default_str();
  cmd.add_option("--embree-isa", args.embree_isa,
                 "Embree's kernels: best (Embree's choice for this CPU), or restricted to sse2, sse4.2, avx, avx2 "
                 "or avx512, e.g. to match the instruction set raylab was built for")
      ->check(CLI::IsMember({"best", "sse2", "sse4.2", "avx", "avx2", "avx512"}))
      ->capture_default_str();
  cmd.add_flag("--bvh-spatial-splits", args.spatial_splits,
               "Build our BVH with spatial splits (SBVH) too; Embree stays at its medium quality");
  cmd.option_defaults()->group("Ray and hit files");
  cmd.add_option("--rays-file", args.rays_file,
                 "Trace the rays of this .rays file (closest hit, singles and packets) instead of generated ones")
      ->excludes(rays);
  cmd.add_option("--rays-out", args.rays_out, "Write the rays of the last traced set as a .rays file");
  cmd.add_option("--hits-out", args.hits_out, "Write our closest hits of the last traced set as a .hits file");
  cmd.add_option("--json", args.json, "Also write the results as JSON to this file ('-': stdout)");
  cmd.option_defaults()->group("Reporting");
  add_loading_flags(cmd, args.allow_outside_paths, args.quiet, "No progress lines on stderr");
}

}  // namespace

CommandRunner add_bench_command(CLI::App& app) {
  return add_command<BenchArgs>(
      app, "bench",
      "Our accelerator against Embree 3 on the same rays: agreement, single-ray and packet Mrays/s, build speed, "
      "memory and SAH cost, each with the ratio ours/Embree",
      add_options, run);
}

}  // namespace raylab::cli
