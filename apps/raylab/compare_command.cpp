// `raylab compare`: argument parsing and printing only; the measuring is in the library
// (lab/accel_compare.h), its heat maps and chart in lab/compare_charts.h.

#include <fmt/core.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accel_options.h"
#include "camera_options.h"
#include "command_setup.h"
#include "commands.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/scene_loader.h"
#include "raylab/lab/accel_compare.h"
#include "raylab/lab/compare_charts.h"
#include "raylab/render/image_size.h"

namespace raylab::cli {
namespace {

// Exit code when two structures disagree on some ray (after the table and the rays are printed).
constexpr int kDisagreementExit = kExitDisagreement;
// Width of the primary-ray image when none is given; the height follows the scene's aspect.
constexpr int kDefaultWidth = 512;

struct CompareArgs {
  std::string scene;
  std::vector<std::string> accels = default_compare_accels();
  AccelArgs accel;
  std::optional<int> width, height;
  CameraOverride camera;
  int threads = 0;
  int repeat = 3;
  std::uint64_t seed = 0;
  double brute_limit = 60.0;
  std::string csv, json, heatmaps, plot;
  bool allow_outside_paths = false;
  bool quiet = false;
};

int run(const CompareArgs& args) {
  check_table_outputs(args.csv, args.json, args.plot);
  CompareOptions options;
  options.accels = args.accels;
  options.structure = args.accel.options;
  options.structure.wrap = parse_wrap_mode(args.accel.wrap);
  options.threads = args.threads;
  options.repeat = args.repeat;
  options.rays.seed = args.seed;
  options.brute_limit_seconds = args.brute_limit;
  if (!args.quiet) options.on_progress = [](const std::string& line) { fmt::print(stderr, "compare: {}\n", line); };

  LoadOptions load;
  load.allow_outside_paths = args.allow_outside_paths;
  Scene scene = load_scene(args.scene, load);
  check_not_inputs(scene, {&args.csv, &args.json, &args.plot});
  for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  apply_camera_override(scene, args.camera);
  // 512 wide when neither side is given; one side given, the other follows the scene's shape.
  set_image_size(scene, args.width || args.height ? args.width : kDefaultWidth, args.height);
  options.rays.width = scene.settings.width;
  options.rays.height = scene.settings.height;

  const CompareResult result = compare_accelerators(scene, options);
  fmt::print("{}", format_compare_table(result, args.scene));
  const std::string mismatches = format_mismatches(result);
  if (!mismatches.empty()) fmt::print("\n{}", mismatches);
  std::fflush(stdout);

  if (!args.csv.empty()) write_text_atomically(args.csv, format_compare_csv(result));
  if (!args.json.empty()) write_text_atomically(args.json, format_compare_json(result, args.scene));
  if (!args.plot.empty()) write_compare_chart(result, args.scene, args.plot);
  std::vector<std::string> written;
  if (!args.heatmaps.empty()) written = write_compare_heatmaps(result, args.heatmaps);
  if (!args.quiet) {
    print_written({&args.csv, &args.json, &args.plot});
    for (const std::string& path : written) fmt::print(stderr, "wrote {}\n", path);
  }
  if (!result.agreed()) {
    fmt::print(stderr, "raylab: the structures disagree with {} (rays printed above)\n", result.reference);
    return kDisagreementExit;
  }
  return 0;
}

void add_options(CLI::App& cmd, CompareArgs& args) {
  cmd.option_defaults()->group("Measurement");
  add_scene_argument(cmd, args.scene);
  std::string names;
  for (const std::string& n : args.accels) names += (names.empty() ? "" : ",") + n;
  cmd.add_option("--accels", args.accels,
                 "Structures to compare, comma-separated, in table order (default: " + names + ")")
      ->delimiter(',')
      ->check(CLI::IsMember(accelerator_choices()));
  cmd.add_option("--width", args.width, "Primary rays per row (default 512)")->check(CLI::Range(1, 16384));
  cmd.add_option("--height", args.height, "Rows of primary rays (default: from the scene's aspect ratio)")
      ->check(CLI::Range(1, 16384));
  add_camera_options(cmd, args.camera);
  add_threads_option(cmd, args.threads);
  cmd.add_option("--repeat", args.repeat, "Timed passes per ray kind; the median is reported")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd.add_option("--seed", args.seed, "Seed of the light samples and bounce directions")
      ->check([](const std::string& v) { return v.starts_with('-') ? "the seed must not be negative" : ""; })
      ->capture_default_str();
  cmd.add_option("--brute-limit", args.brute_limit, "Skip brute force when its estimated time exceeds this (seconds)")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str();
  cmd.option_defaults()->group("Structure parameters");
  add_accel_parameter_options(cmd, args.accel);
  cmd.option_defaults()->group("Output");
  add_table_output_options(cmd, args.csv, args.json, args.plot,
                           "Write an SVG chart of Mrays/s, build time and memory per structure");
  cmd.add_option(
      "--heatmaps", args.heatmaps,
      "Write DIR/<structure>-tests.png and -nodes.png: traversal cost per pixel of the primary rays, one "
      "colour scale for all structures, each the size of the rays' image with its legend in -tests.legend.png "
      "(the folder is created if missing)");
  cmd.option_defaults()->group("Reporting");
  add_loading_flags(cmd, args.allow_outside_paths, args.quiet, "No progress lines on stderr");
}

}  // namespace

CommandRunner add_compare_command(CLI::App& app) {
  return add_command<CompareArgs>(app, "compare",
                                  "Build every acceleration structure for a scene, trace the same rays through each, "
                                  "and tabulate build time, memory, Mrays/s, traversal work and agreement",
                                  add_options, run);
}

}  // namespace raylab::cli
