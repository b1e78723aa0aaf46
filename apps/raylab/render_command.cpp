// `raylab render`: argument parsing and reporting only; the work is in the library.

#include <fmt/core.h>
#include <unistd.h>

#include <csignal>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accel_options.h"
#include "commands.h"
#include "raylab/accel/factory.h"
#include "raylab/accel/two_level.h"
#include "raylab/core/error.h"
#include "raylab/core/interrupt.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/checkpoint_file.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/heatmap.h"
#include "raylab/io/image_io.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/adaptive.h"
#include "raylab/render/progress.h"
#include "raylab/render/renderer.h"
#include "raylab/render/spd_protocol.h"
#include "raylab/sampling/filter.h"
#include "raylab/sampling/pixel_sampler.h"
#include "raylab/scene/builtin_scenes.h"
#include "raylab/scene/scene_fingerprint.h"
#include "raylab/scene/spd.h"

namespace raylab::cli {
namespace {

std::string human_bytes(std::size_t bytes) {
  if (bytes < 1024) return fmt::format("{} B", bytes);
  if (bytes < 1024 * 1024) return fmt::format("{:.1f} KiB", bytes / 1024.0);
  if (bytes < std::size_t(1) << 30) return fmt::format("{:.1f} MiB", bytes / (1024.0 * 1024.0));
  return fmt::format("{:.1f} GiB", bytes / (1024.0 * 1024.0 * 1024.0));
}

struct RenderArgs {
  std::string scene = "demo";
  const CLI::Option* scene_option = nullptr;  // to tell a scene given from the default
  std::string output = "render.png";
  std::optional<int> width, height, spp, max_depth;
  std::optional<std::uint64_t> seed;
  std::optional<std::string> sampler, filter;
  std::optional<float> filter_radius, aa_threshold;
  std::optional<int> aa_depth;
  std::vector<std::string> aovs;
  std::string accel = "bvh";
  const CLI::Option* accel_option = nullptr;
  AccelArgs structure;
  int threads = 0;
  std::string packets = "on";
  bool stats = false;
  bool quiet = false;
  bool allow_outside_paths = false;
  bool list_scenes = false;
  bool spd_protocol = false;
  std::optional<int> passes;
  std::optional<std::string> checkpoint, resume;
  double checkpoint_every = 60.0;
  std::optional<std::string> max_memory;
};

// Bytes in a size such as "512M", "8G", "1.5T" or "1000000" (powers of 1024); nullopt when it
// is not one.
std::optional<std::size_t> parse_byte_size(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  const std::string unit = text.substr(used);
  double scale = 1;
  if (unit == "K" || unit == "k" || unit == "KiB")
    scale = 1024.0;
  else if (unit == "M" || unit == "MiB")
    scale = 1024.0 * 1024;
  else if (unit == "G" || unit == "GiB")
    scale = 1024.0 * 1024 * 1024;
  else if (unit == "T" || unit == "TiB")
    scale = 1024.0 * 1024 * 1024 * 1024;
  else if (!unit.empty() && unit != "B")
    return std::nullopt;
  const double bytes = value * scale;
  if (!(bytes > 0) || bytes > 1e18) return std::nullopt;
  return static_cast<std::size_t>(bytes);
}

// The default memory limit: 80% of this machine's physical memory.
std::size_t default_memory_limit() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::size_t(1) << 40;  // unknown: no practical limit
  return static_cast<std::size_t>(static_cast<double>(pages) * static_cast<double>(page) * 0.8);
}

// Refuses (UsageError) a render whose estimated memory exceeds the limit, with both figures.
void check_memory(const RenderMemoryEstimate& e, std::uint64_t primitives, const std::optional<std::string>& max) {
  const std::size_t limit = max ? *parse_byte_size(*max) : default_memory_limit();
  if (e.total() <= limit) return;
  throw UsageError(fmt::format(
      "this render would need about {} (image {}, per-tile sums {}, acceleration structure {} for {} primitives; "
      "{} primary samples), more than the limit of {}{}; lower --width or --height, or raise --max-memory",
      human_bytes(e.total()), human_bytes(e.image), human_bytes(e.sums), human_bytes(e.accelerator), primitives,
      e.samples, human_bytes(limit), max ? " (--max-memory)" : " (80% of this machine's memory)"));
}

// Fills what the command line leaves unsaid from the checkpoint being resumed, so that
// `raylab render --resume FILE` alone goes on with the same scene and settings.
void fill_from_checkpoint(RenderArgs& a, const RenderCheckpoint& saved, const std::string& path) {
  auto value = [&](const char* name) { return saved_setting(saved, name); };
  auto parse = [&](const char* name, auto convert) {
    try {
      return convert(*value(name));
    } catch (const std::exception&) {
      throw InputError(path, std::string("the checkpoint's setting '") + name + "' is not a valid value");
    }
  };
  auto fill_int = [&](std::optional<int>& field, const char* name) {
    if (!field && value(name)) field = parse(name, [](const std::string& v) { return std::stoi(v); });
  };
  if (a.scene_option->count() == 0) a.scene = saved.scene;
  fill_int(a.width, "width");
  fill_int(a.height, "height");
  fill_int(a.spp, "spp");
  fill_int(a.max_depth, "max depth");
  fill_int(a.passes, "passes");
  if (!a.seed && value("seed")) a.seed = parse("seed", [](const std::string& v) { return std::stoull(v); });
  if (!a.sampler && value("sampler")) a.sampler = *value("sampler");
  if (!a.filter && value("filter")) a.filter = *value("filter");
  if (!a.filter_radius && value("filter radius")) {
    a.filter_radius = parse("filter radius", [](const std::string& v) { return std::stof(v); });
  }
  if (a.accel_option->count() == 0 && value("accel")) a.accel = *value("accel");
}

// "3, 5-9, 12": sorted indices as ranges.
std::string index_ranges(const std::vector<int>& indices) {
  std::string out;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    if (!out.empty()) out += ", ";
    out += std::to_string(indices[i]);
    if (j > i) out += "-" + std::to_string(indices[j]);
    i = j + 1;
  }
  return out;
}

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

void list_scenes() {
  fmt::print("built-in scenes:\n");
  for (auto name : builtin_scene_names()) fmt::print("  {}\n", name);
  fmt::print("SPD generators (spd:NAME or spd:NAME?size=N):\n");
  for (const SpdGenerator& g : spd_generators()) {
    fmt::print("  spd:{:<8} size 1..{}, default {}: {}\n", g.name, g.max_size, g.default_size, g.description);
  }
  std::string extensions;
  for (auto e : scene_file_extensions()) extensions += (extensions.empty() ? "" : " ") + std::string(e);
  fmt::print("scene and mesh files: {}\n", extensions);
}

void print_protocol_counts(const SpdProtocolCounts& c) {
  fmt::print("SPD protocol: 512x512, eye rays through the 513x513 pixel corners, depth 5\n");
  fmt::print("{:<20}{:>14}{:>14}\n", "rays", "cast", "hit");
  fmt::print("{:<20}{:>14}{:>14}\n", "primary", c.primary, c.primary_hits);
  fmt::print("{:<20}{:>14}{:>14}\n", "shadow", c.shadow, c.shadow_hits);
  fmt::print("{:<20}{:>14}{:>14}\n", "secondary", c.secondary, c.secondary_hits);
}

std::vector<std::string> sampler_choices() {
  std::vector<std::string> names{"auto"};
  for (auto n : render_sampler_names()) names.emplace_back(n);
  return names;
}

bool wants_samples_aov(const RenderArgs& args) {
  return std::find(args.aovs.begin(), args.aovs.end(), "samples") != args.aovs.end();
}

// OUTPUT with its extension replaced by `suffix` ("render.png" -> "render.samples.png").
std::string beside_output(const std::string& output, const std::string& suffix) {
  const std::filesystem::path p(output);
  return (p.parent_path() / p.stem()).string() + suffix;
}

// The image, and the sample-count outputs asked for by --aov samples: an EXR layer (in the
// output itself when it is an EXR, else in OUTPUT.samples.exr) and a false-colour PNG.
void write_outputs(const RenderArgs& args, const Film& film, const RenderResult& result) {
  if (!wants_samples_aov(args)) {
    write_image(film, args.output);
    return;
  }
  ImageLayer layer{"samples.Y", {}};
  layer.values.assign(result.samples_per_pixel.begin(), result.samples_per_pixel.end());
  const std::vector<ImageLayer> layers{layer};
  if (lowercase_extension(args.output) == ".exr") {
    write_image(film, args.output, layers);
  } else {
    write_image(film, args.output);
    write_image(film, beside_output(args.output, ".samples.exr"), layers);
  }
  write_sample_count_png(result.samples_per_pixel, film.width(), film.height(),
                         beside_output(args.output, ".samples.png"));
}

int run(const RenderArgs& given) {
  if (given.list_scenes) {
    list_scenes();
    return 0;
  }
  if (given.spd_protocol && (given.width || given.height || given.spp || given.max_depth)) {
    throw UsageError("--spd-protocol fixes the image size, samples and depth (512x512, corner rays, depth 5)");
  }
  if (given.spd_protocol && (given.passes || given.checkpoint || given.resume)) {
    throw UsageError("--spd-protocol renders in one go: no --passes, --checkpoint or --resume");
  }
  // Until the render starts there is nothing to save: a signal ends the run at once.
  install_interrupt_handlers(remove_pending_temporary_files, true);
  RenderArgs args = given;
  std::optional<RenderCheckpoint> saved;
  if (args.resume) {
    saved = read_checkpoint(*args.resume);
    fill_from_checkpoint(args, *saved, *args.resume);
  }
  check_image_extension(args.output);  // usage error before any work
  check_writable(args.output);         // input error before any work
  if (wants_samples_aov(args)) {
    check_writable(beside_output(args.output, ".samples.png"));
    if (lowercase_extension(args.output) != ".exr") check_writable(beside_output(args.output, ".samples.exr"));
  }
  LoadOptions load;
  load.allow_outside_paths = args.allow_outside_paths;
  Scene scene = load_scene(args.scene, load);
  for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  // Of the scene as loaded, before the command line's settings (which a checkpoint lists apart).
  const std::uint64_t fingerprint = scene_fingerprint(scene);
  RenderSettings& s = scene.settings;
  if (args.width) s.width = *args.width;
  if (args.height) s.height = *args.height;
  if (args.spp) s.spp = *args.spp;
  if (args.max_depth) s.max_depth = *args.max_depth;
  if (args.seed) s.seed = *args.seed;
  if (args.sampler) s.sampler = *args.sampler;
  if (args.filter) s.filter = *args.filter;
  if (args.filter_radius) s.filter_radius = *args.filter_radius;
  if (args.aa_threshold) s.aa_threshold = *args.aa_threshold;
  if (args.aa_depth) s.aa_depth = *args.aa_depth;
  const std::string sampler = resolve_sampler_name(s);
  if ((args.aa_threshold || args.aa_depth) && !is_adaptive_sampler(sampler)) {
    throw UsageError(
        "--aa-threshold and --aa-depth apply to the adaptive samplers (--sampler adaptive or "
        "adaptive-corners), not to " +
        sampler);
  }
  check_sampling_settings(s);  // usage errors before any work
  const bool long_render = args.passes || args.checkpoint || args.resume;
  if (long_render && is_adaptive_sampler(sampler)) {
    throw UsageError("--passes, --checkpoint and --resume work with the uniform samplers, not with " + sampler +
                     " (its refinement needs the whole image at once)");
  }
  RenderOptions options;
  RenderCheckpoint header{
      args.scene, fingerprint, image_settings(s, sampler, options.tile_size, args.passes.value_or(1), args.accel), {}};
  RenderProgress progress;
  if (saved) {
    const std::vector<std::string> differences = checkpoint_differences(*saved, header);
    if (!differences.empty()) {
      std::string message = "cannot resume: this render differs from the checkpoint's";
      for (const std::string& d : differences) message += "\n  " + d;
      throw InputError(*args.resume, message);
    }
    progress = std::move(saved->progress);
  }
  // Where checkpoints go: --checkpoint, else the checkpoint resumed, else beside the output (only
  // written if the render is interrupted).
  const std::string checkpoint_path = args.checkpoint ? *args.checkpoint
                                      : args.resume   ? *args.resume
                                                      : beside_output(args.output, ".ckpt");
  check_writable(checkpoint_path);
  if (args.checkpoint || args.resume) {  // (long renders are uniform-sampler renders: checked above)
    options.checkpoint_seconds = args.checkpoint_every;
    options.on_checkpoint = [&](const RenderProgress& state) {
      RenderCheckpoint checkpoint = header;
      checkpoint.progress = state;
      try {
        write_checkpoint(checkpoint_path, checkpoint);
      } catch (const InputError& e) {  // the render goes on; the next checkpoint may succeed
        fmt::print(stderr, "\nwarning: checkpoint not written: {}\n", e.what());
      }
    };
  }
  // Before the accelerator or the image is allocated: refuse what cannot fit (the estimate counts
  // the copies that checkpoints take).
  check_memory(estimate_render_memory(scene, options), scene.primitive_count(), args.max_memory);

  SceneAccelOptions structure = args.structure.options;
  structure.top = args.accel;
  structure.wrap = parse_wrap_mode(args.structure.wrap);
  const std::unique_ptr<Accelerator> accel =
      make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, structure);
  if (args.spd_protocol) {
    Film film(kSpdProtocolSize, kSpdProtocolSize);
    options.threads = args.threads;
    options.count_traversal = args.stats;
    const SpdProtocolResult result = render_spd_protocol(scene, *accel, film, options);
    write_image(film, args.output);
    print_protocol_counts(result.counts);
    if (args.stats) print_stats(result.stats, accel->info(), result.seconds);
    if (!args.quiet) fmt::print("wrote {} in {}\n", args.output, ProgressBar::format_duration(result.seconds));
    return 0;
  }
  Film film(s.width, s.height);
  const bool interactive = ::isatty(STDERR_FILENO) != 0;
  std::optional<ProgressBar> bar;
  if (!args.quiet) bar.emplace("render", stderr, interactive);
  options.threads = args.threads;
  options.count_traversal = args.stats;
  options.packets = args.packets == "on";
  if (bar) options.on_progress = [&bar](int done, int total) { bar->update(done, total); };
  const bool uniform = !is_adaptive_sampler(sampler);
  if (uniform) {
    options.passes = args.passes.value_or(1);
    options.progress = &progress;
    options.should_stop = [] { return interrupt_signal() != 0; };
    options.on_pass = [&](int done, const Film& image) {
      write_image(image, args.output);
      if (!args.quiet)
        fmt::print(stderr, "{}pass {}/{}: wrote {}\n", interactive ? "\n" : "", done, options.passes, args.output);
    };
  }
  // From here the first signal lets the tiles under way finish, then the partial image and a
  // checkpoint are written; the adaptive samplers cannot stop part-way, so a signal ends them.
  install_interrupt_handlers(remove_pending_temporary_files, !uniform);
  const RenderResult result = render(scene, *accel, film, options);
  if (result.interrupted) {
    const int signal = interrupt_signal();
    if (bar) bar->finish("interrupted");
    write_outputs(args, film, result);
    header.progress = std::move(progress);
    write_checkpoint(checkpoint_path, header);
    const RenderProgress& p = header.progress;
    const std::vector<int> unfinished = p.unfinished_tiles();
    fmt::print(stderr,
               "raylab: interrupted by {}: wrote the partial image {} and the checkpoint {}\n"
               "  pass {} of {}: {} of {} tiles unfinished{}: {}\n"
               "  resume with the same command and --resume {}\n",
               signal == SIGTERM ? "SIGTERM" : "SIGINT", args.output, checkpoint_path, p.passes_done + 1, p.passes,
               unfinished.size(), p.tile_count(), p.passes_done == 0 ? " (black in the image)" : "",
               index_ranges(unfinished), checkpoint_path);
    return interrupt_exit_status(signal);
  }
  const double mrays = result.seconds > 0 ? result.stats.total_rays() / result.seconds * 1e-6 : 0.0;
  const double pixels = static_cast<double>(s.width) * s.height;
  const std::string sampling =
      is_adaptive_sampler(sampler)
          ? fmt::format("{}, {:.2f} primary rays per pixel", sampler,
                        static_cast<double>(result.primary_rays()) / pixels)
          : fmt::format("{} spp {}", result.samples_per_pixel.empty() ? s.spp : int(result.samples_per_pixel[0]),
                        sampler);
  if (bar)
    bar->finish(fmt::format("{}x{}, {}, {} rays ({:.2f} Mrays/s)", s.width, s.height, sampling,
                            result.stats.total_rays(), mrays));
  for (const std::string& n : result.notices) fmt::print(stderr, "note: {}\n", n);
  if (result.stats.nonfinite_samples > 0) {
    fmt::print(stderr, "warning: {} samples had NaN or infinite radiance and were replaced by black\n",
               result.stats.nonfinite_samples);
  }
  write_outputs(args, film, result);
  // The image is whole: a checkpoint of this render is of no more use.
  std::error_code removed;
  if ((args.checkpoint || args.resume) && std::filesystem::remove(checkpoint_path, removed) && !args.quiet) {
    fmt::print(stderr, "note: removed the checkpoint {} (the render is complete)\n", checkpoint_path);
  }
  if (args.stats) print_stats(result.stats, accel->info(), result.seconds);
  if (!args.quiet) {
    fmt::print("wrote {} ({}x{}, {}, {} primary rays, --accel {}) in {}\n", args.output, s.width, s.height, sampling,
               result.primary_rays(), args.accel, ProgressBar::format_duration(result.seconds));
  }
  return 0;
}

}  // namespace

CommandRunner add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image (.png, .exr or .pfm)");
  args->scene_option =
      cmd->add_option("scene", args->scene,
                      "Scene: a built-in name (demo, cornell), an SPD generator (spd:balls, spd:balls?size=6), or a "
                      "file (.json .nff .obj .gltf .glb .ply .off .stl); see --list-scenes")
          ->capture_default_str();
  cmd->add_option("-o,--output", args->output, "Output image; format from the extension: .png .exr .pfm")
      ->capture_default_str();
  cmd->add_option("--width", args->width, "Image width in pixels")->check(CLI::Range(1, 32768));
  cmd->add_option("--height", args->height, "Image height in pixels")->check(CLI::Range(1, 32768));
  cmd->add_option("--spp", args->spp,
                  "Samples per pixel; a count the sampler cannot use is rounded with a notice. Adaptive "
                  "samplers: the most samples a pixel may get (sets --aa-depth to floor(log4 spp))")
      ->check(CLI::Range(1, 1 << 16));
  cmd->add_option("--sampler", args->sampler,
                  "Sample placement: auto (center at 1 spp, else jittered), center, regular, random, jittered, "
                  "cmj, sobol, adaptive-corners, adaptive")
      ->check(CLI::IsMember(sampler_choices()));
  cmd->add_option("--filter", args->filter, "Reconstruction filter: box (default), tent, gaussian, mitchell")
      ->check(CLI::IsMember(std::vector<std::string>(filter_names().begin(), filter_names().end())));
  cmd->add_option("--filter-radius", args->filter_radius,
                  "Filter half-width in pixels (default: box 0.5, tent 1, gaussian 1.5, mitchell 2)")
      ->check(CLI::Range(0.5f, 8.f));
  cmd->add_option("--aa-threshold", args->aa_threshold,
                  "Adaptive samplers: display-encoded colour difference that triggers refinement (default 0.1)")
      ->check(CLI::Range(0.f, 1.f));
  cmd->add_option("--aa-depth", args->aa_depth,
                  "Adaptive samplers: most subdivision levels (a pixel holds at most 4^depth cells)")
      ->check(CLI::Range(0, 8));
  cmd->add_option("--aov", args->aovs,
                  "Extra outputs: 'samples' writes the primary samples per pixel as an EXR layer (into an .exr "
                  "output, else OUTPUT.samples.exr) and a false-colour OUTPUT.samples.png")
      ->check(CLI::IsMember({"samples"}))
      ->delimiter(',');
  args->accel_option = cmd->add_option("--accel", args->accel, "Acceleration structure")
                           ->check(CLI::IsMember(accelerator_choices()))
                           ->capture_default_str();
  add_accel_parameter_options(*cmd, args->structure);
  cmd->add_option("--threads", args->threads, "Worker threads; 0 = all cores")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option("--packets", args->packets,
                  "Trace primary rays in packets of 16 and shadow rays toward point and directional lights as "
                  "one packet per light: on or off. The image and ray counts are identical either way; the "
                  "adaptive samplers always trace single rays")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  // CLI11 (2.1) would read "-1" into the unsigned seed as 2^64 - 1 without a word.
  cmd->add_option("--seed", args->seed, "Seed of every random choice (default: the scene's, 0)")
      ->check([](const std::string& v) { return v.starts_with('-') ? "the seed must not be negative" : ""; });
  cmd->add_option("--max-depth", args->max_depth, "Ray tree depth; 1 = eye rays only (default 5)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--passes", args->passes,
                  "Take the samples in this many passes over the whole image, writing the image after each "
                  "(uniform samplers; 1 to spp)")
      ->check(CLI::Range(1, 1 << 16));
  cmd->add_option("--checkpoint", args->checkpoint,
                  "Save the render's progress to this file every --checkpoint-every seconds (removed when the "
                  "render completes); an interrupted render always saves one (default: OUTPUT.ckpt)");
  cmd->add_option("--checkpoint-every", args->checkpoint_every, "Seconds between checkpoints")
      ->check(CLI::Range(0.001, 1e9))
      ->capture_default_str();
  cmd->add_option("--resume", args->resume,
                  "Go on with the render saved in this checkpoint (settings not given are taken from it; a "
                  "checkpoint of another scene or other settings is refused); the image is byte-identical to an "
                  "uninterrupted render");
  cmd->add_option("--max-memory", args->max_memory,
                  "Refuse a render whose estimated memory exceeds this (e.g. 512M, 8G; default: 80% of the "
                  "machine's memory)")
      ->check([](const std::string& v) { return parse_byte_size(v) ? "" : "expected a size such as 512M or 8G"; });
  cmd->add_flag("--stats", args->stats, "Print ray counts, traversal work and timings after the render");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress bar and no summary");
  cmd->add_flag("--allow-outside-paths", args->allow_outside_paths,
                "Let a scene file reference files outside its own folder");
  cmd->add_flag("--list-scenes", args->list_scenes, "List the built-in scenes and SPD generators, then exit");
  cmd->add_flag("--spd-protocol", args->spd_protocol,
                "Render by the SPD testing procedure (512x512, rays through pixel corners, depth 5) and print "
                "the ray-count invariants");
  return [args] { return run(*args); };
}

}  // namespace raylab::cli
