// `raylab quality`: argument parsing and printing only; the study is in the library
// (lab/quality_study.h), the reference cache and the chart in lab/quality_reference.h and
// lab/quality_chart.h.

#include <fmt/core.h>
#include <unistd.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "camera_options.h"
#include "command_setup.h"
#include "commands.h"
#include "raylab/accel/two_level.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/scene_loader.h"
#include "raylab/lab/quality_chart.h"
#include "raylab/lab/quality_reference.h"
#include "raylab/lab/quality_study.h"
#include "raylab/render/image_size.h"
#include "raylab/render/progress.h"
#include "raylab/sampling/filter.h"

namespace raylab::cli {
namespace {

struct QualityArgs {
  std::string scene;
  std::string reference = "auto";
  std::string budgets = "1,4,16,64";
  std::string samplers;  // empty: all
  int seeds = 5;
  std::optional<int> width, height;
  CameraOverride camera;
  std::optional<std::string> filter;
  std::optional<float> filter_radius;
  std::optional<float> aa_threshold;
  int reference_spp = 1024;
  std::string cache_dir;  // empty: default_reference_cache_dir()
  int threads = 0;
  std::string csv, json, plot;
  bool allow_outside_paths = false;
  bool quiet = false;
};

// The study's options from the arguments, checked (usage errors before any work).
QualityOptions quality_options(const QualityArgs& args) {
  QualityOptions options;
  options.budgets = parse_budget_list(args.budgets);
  if (!args.samplers.empty()) options.samplers = parse_sampler_list(args.samplers);
  options.seeds = args.seeds;
  options.reference = args.reference;
  options.reference_spp = args.reference_spp;
  options.threads = args.threads;
  options.cache_dir = args.cache_dir.empty() ? default_reference_cache_dir() : args.cache_dir;
  validate_quality_options(options);
  if (args.filter) make_filter(*args.filter, args.filter_radius.value_or(0.f));  // a bad name before the scene loads
  return options;
}

// The scene with the image size and the filter the arguments set.
Scene study_scene(const QualityArgs& args) {
  LoadOptions load;
  load.allow_outside_paths = args.allow_outside_paths;
  Scene scene = load_scene(args.scene, load);
  for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  apply_camera_override(scene, args.camera);
  set_image_size(scene, args.width, args.height);
  RenderSettings& s = scene.settings;
  if (args.filter) s.filter = *args.filter;
  if (args.filter_radius) s.filter_radius = *args.filter_radius;
  if (args.aa_threshold) s.aa_threshold = *args.aa_threshold;
  make_filter(s.filter, s.filter_radius);  // the scene's own filter, checked before the work
  return scene;
}

// The reference: the image given (which must be the study's size), else the cached or rendered one.
ReferenceImage study_reference(const QualityArgs& args, const QualityOptions& options, const Scene& scene,
                               const Accelerator& accel, std::optional<Film>& given) {
  const RenderSettings& s = scene.settings;
  ReferenceImage reference;
  if (given) {
    if (given->width() != s.width || given->height() != s.height) {
      throw InputError(options.reference, fmt::format("the reference image is {}x{} but the study renders {}x{} "
                                                      "(give --width {} --height {}, or another reference)",
                                                      given->width(), given->height(), s.width, s.height,
                                                      given->width(), given->height()));
    }
    reference.film = std::move(*given);
    reference.description = options.reference;
  } else {
    std::optional<ProgressBar> bar;
    if (!args.quiet) bar.emplace("reference", stderr, ::isatty(STDERR_FILENO) != 0);
    reference = obtain_reference(scene, accel, options, [&bar](int done, int total) {
      if (bar) bar->update(done, total);
    });
    if (bar && reference.rendered) bar->finish(fmt::format("{}x{}, {} spp", s.width, s.height, options.reference_spp));
  }
  if (!args.quiet) fmt::print(stderr, "reference: {}\n", reference.description);
  return reference;
}

int run(const QualityArgs& args) {
  QualityOptions options = quality_options(args);
  check_table_outputs(args.csv, args.json, args.plot);
  // A named reference is read first: a missing file should not wait for the scene to load.
  std::optional<Film> given;
  if (options.reference != "auto") given = load_reference_file(options.reference);
  const Scene scene = study_scene(args);
  check_not_inputs(scene, {&args.csv, &args.json, &args.plot});
  options.reference_key = scene_source_key(args.scene);
  // The camera flags change the reference image as much as the scene's own file would.
  if (!args.camera.empty()) options.reference_key += " camera " + describe_camera_override(args.camera);
  const std::unique_ptr<Accelerator> accel =
      make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, SceneAccelOptions{});
  const ReferenceImage reference = study_reference(args, options, scene, *accel, given);

  std::optional<ProgressBar> bar;
  if (!args.quiet) {
    bar.emplace("quality", stderr, ::isatty(STDERR_FILENO) != 0);
    options.on_progress = [&bar](double fraction, const std::string&) {
      bar->update(static_cast<int>(fraction * 1000.0), 1000);
    };
  }
  QualityResult result = run_quality_study(scene, *accel, reference.film, options);
  result.reference = reference.description;
  if (bar) bar->finish(fmt::format("{} rows", result.rows.size()));

  fmt::print("{}", format_quality_table(result, args.scene));
  if (const std::optional<BarRatios> ratios = bar_ratios(result)) fmt::print("\n{}\n", format_bar_ratios(*ratios));
  std::fflush(stdout);

  if (!args.csv.empty()) write_text_atomically(args.csv, format_quality_csv(result));
  if (!args.json.empty()) write_text_atomically(args.json, format_quality_json(result, args.scene));
  if (!args.plot.empty()) write_quality_chart(result, args.scene, args.plot);
  if (!args.quiet) print_written({&args.csv, &args.json, &args.plot});
  return 0;
}

void add_options(CLI::App& cmd, QualityArgs& args) {
  cmd.option_defaults()->group("Study");
  add_scene_argument(cmd, args.scene);
  cmd.add_option("--reference", args.reference,
                 "Reference image (.exr or .pfm, the study's size), or 'auto': rendered with --reference-spp "
                 "jittered samples and cached")
      ->capture_default_str();
  cmd.add_option("--budgets", args.budgets,
                 "Samples per pixel to study, comma-separated (adaptive samplers: the most per pixel)")
      ->capture_default_str();
  std::string names;
  for (const std::string& n : quality_sampler_names()) names += (names.empty() ? "" : ",") + n;
  cmd.add_option("--samplers", args.samplers, "Samplers, comma-separated, in table order (default: " + names + ")");
  cmd.add_option("--seeds", args.seeds, "Renders per row, seeds 0..K-1 (center, regular, adaptive-corners: one)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd.option_defaults()->group("Image and filter");
  cmd.add_option("--width", args.width, "Image width (default: the scene's)")->check(CLI::Range(1, 16384));
  cmd.add_option("--height", args.height, "Image height (default: the scene's)")->check(CLI::Range(1, 16384));
  add_camera_options(cmd, args.camera);
  cmd.add_option("--filter", args.filter,
                 "Reconstruction filter: box, tent, gaussian, mitchell (default: the scene's)");
  cmd.add_option("--filter-radius", args.filter_radius, "Filter radius in pixels; 0 = the filter's default");
  cmd.add_option("--aa-threshold", args.aa_threshold,
                 "Adaptive samplers: colour difference that triggers refinement (default: the sampler's)")
      ->check(CLI::Range(0.f, 1.f));
  cmd.option_defaults()->group("Reference");
  cmd.add_option("--reference-spp", args.reference_spp, "Samples per pixel of an auto reference (jittered)")
      ->check(CLI::Range(1, 65536))
      ->capture_default_str();
  cmd.add_option("--cache-dir", args.cache_dir,
                 "Folder of cached auto references (default: $XDG_CACHE_HOME/raylab/references, else "
                 "~/.cache/raylab/references)");
  cmd.option_defaults()->group("Performance");
  add_threads_option(cmd, args.threads);
  cmd.option_defaults()->group("Output");
  add_table_output_options(cmd, args.csv, args.json, args.plot,
                           "Write an SVG chart: RMSE against primary rays per pixel, log-log");
  cmd.option_defaults()->group("Reporting");
  add_loading_flags(cmd, args.allow_outside_paths, args.quiet, "No progress on stderr");
}

}  // namespace

CommandRunner add_quality_command(CLI::App& app) {
  return add_command<QualityArgs>(
      app, "quality",
      "Render a scene with every pixel sampler at several sample budgets and seeds, and tabulate the error "
      "against a reference image (RMSE, PSNR, SSIM, 99.9th percentile) against the rays and time spent",
      add_options, run);
}

}  // namespace raylab::cli
