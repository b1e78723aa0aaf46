#include "render_setup.h"

#include <fmt/core.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>

#include "raylab/accel/two_level.h"
#include "raylab/core/byte_size.h"
#include "raylab/core/error.h"
#include "raylab/core/hash64.h"
#include "raylab/core/index_ranges.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/heatmap.h"
#include "raylab/io/image_io.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/adaptive.h"
#include "raylab/scene/scene_fingerprint.h"

namespace raylab::cli {
namespace {

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

bool wants_samples_aov(const RenderArgs& args) {
  return std::find(args.aovs.begin(), args.aovs.end(), "samples") != args.aovs.end();
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

std::string beside_output(const std::string& output, const std::string& suffix) {
  const std::filesystem::path p(output);
  return (p.parent_path() / p.stem()).string() + suffix;
}

void print_interrupted(int signal, const std::string& output, const std::string& checkpoint_path,
                       const RenderProgress& p) {
  const std::vector<int> unfinished = p.unfinished_tiles();
  fmt::print(stderr,
             "raylab: interrupted by {}: wrote the partial image {} and the checkpoint {}\n"
             "  pass {} of {}: {} of {} tiles unfinished{}: {}\n"
             "  resume with the same command and --resume {}\n",
             signal == SIGTERM ? "SIGTERM" : "SIGINT", output, checkpoint_path, p.passes_done + 1, p.passes,
             unfinished.size(), p.tile_count(), p.passes_done == 0 ? " (black in the image)" : "",
             index_ranges(unfinished), checkpoint_path);
}

void print_warnings(const RenderResult& result) {
  for (const std::string& n : result.notices) fmt::print(stderr, "note: {}\n", n);
  if (result.stats.nonfinite_samples > 0) {
    fmt::print(stderr, "warning: {} samples had NaN or infinite radiance and were replaced by black\n",
               result.stats.nonfinite_samples);
  }
}

void remove_finished_checkpoint(const RenderSetup& setup) {
  // The image is whole: a checkpoint of this render is of no more use.
  std::error_code removed;
  if (saves_checkpoints(setup.args) && std::filesystem::remove(setup.checkpoint_path, removed) && !setup.args.quiet) {
    fmt::print(stderr, "note: removed the checkpoint {} (the render is complete)\n", setup.checkpoint_path);
  }
}

bool saves_checkpoints(const RenderArgs& args) { return args.checkpoint || args.resume; }

std::unique_ptr<RenderSetup> prepare_render(const RenderArgs& given, bool writes_outputs) {
  auto made = std::make_unique<RenderSetup>();
  RenderSetup& setup = *made;
  RenderArgs& args = setup.args;
  args = given;
  std::optional<RenderCheckpoint> saved;
  if (args.resume) {
    saved = read_checkpoint(*args.resume);
    fill_from_checkpoint(args, *saved, *args.resume);
  }
  check_image_extension(args.output);  // usage error before any work
  if (writes_outputs) {
    check_writable(args.output);  // input error before any work
    if (wants_samples_aov(args)) {
      check_writable(beside_output(args.output, ".samples.png"));
      if (lowercase_extension(args.output) != ".exr") check_writable(beside_output(args.output, ".samples.exr"));
    }
  }
  LoadOptions load;
  load.allow_outside_paths = args.allow_outside_paths;
  setup.scene = load_scene(args.scene, load);
  Scene& scene = setup.scene;
  if (writes_outputs) {
    for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
  }
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
  setup.sampler = resolve_sampler_name(s);
  if ((args.aa_threshold || args.aa_depth) && !is_adaptive_sampler(setup.sampler)) {
    throw UsageError(
        "--aa-threshold and --aa-depth apply to the adaptive samplers (--sampler adaptive or "
        "adaptive-corners), not to " +
        setup.sampler);
  }
  check_sampling_settings(s);  // usage errors before any work
  const bool long_render = args.passes || args.checkpoint || args.resume;
  if (long_render && is_adaptive_sampler(setup.sampler)) {
    throw UsageError("--passes, --checkpoint and --resume work with the uniform samplers, not with " + setup.sampler +
                     " (its refinement needs the whole image at once)");
  }
  setup.header =
      RenderCheckpoint{args.scene,
                       fingerprint,
                       image_settings(s, setup.sampler, RenderOptions{}.tile_size, args.passes.value_or(1), args.accel),
                       {}};
  if (saved) {
    const std::vector<std::string> differences = checkpoint_differences(*saved, setup.header);
    if (!differences.empty()) {
      std::string message = "cannot resume: this render differs from the checkpoint's";
      for (const std::string& d : differences) message += "\n  " + d;
      throw InputError(*args.resume, message);
    }
    setup.progress = std::move(saved->progress);
  }
  // Where checkpoints go: --checkpoint, else the checkpoint resumed, else beside the output (only
  // written if the render is interrupted).
  setup.checkpoint_path = args.checkpoint ? *args.checkpoint
                          : args.resume   ? *args.resume
                                          : beside_output(args.output, ".ckpt");
  if (writes_outputs) check_writable(setup.checkpoint_path);
  // Before the accelerator or the image is allocated: refuse what cannot fit (the estimate counts
  // the copies that checkpoints take).
  check_memory(estimate_render_memory(scene, render_options(setup)), scene.primitive_count(), args.max_memory);

  SceneAccelOptions structure = args.structure.options;
  structure.top = args.accel;
  structure.wrap = parse_wrap_mode(args.structure.wrap);
  setup.accel = make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, structure);
  return made;
}

RenderOptions render_options(const RenderSetup& setup) {
  const RenderArgs& args = setup.args;
  RenderOptions options;
  options.threads = args.threads;
  options.count_traversal = args.stats;
  options.packets = args.packets == "on";
  if (is_adaptive_sampler(setup.sampler)) return options;
  options.passes = args.passes.value_or(1);
  if (saves_checkpoints(args)) {
    options.checkpoint_seconds = args.checkpoint_every;
    options.on_checkpoint = [&setup](const RenderProgress& state) {
      RenderCheckpoint checkpoint = setup.header;
      checkpoint.progress = state;
      try {
        write_checkpoint(setup.checkpoint_path, checkpoint);
      } catch (const InputError& e) {  // the render goes on; the next checkpoint may succeed
        fmt::print(stderr, "\nwarning: checkpoint not written: {}\n", e.what());
      }
    };
  }
  return options;
}

std::uint64_t render_agreement(const RenderSetup& setup) {
  Hash64 h;
  h.word(setup.header.scene_fingerprint);
  for (const auto& [name, value] : setup.header.settings) {
    h.bytes(name.data(), name.size());
    h.bytes(value.data(), value.size());
  }
  return h.value();
}

void write_outputs(const RenderArgs& args, const std::string& output, const Film& film,
                   const std::vector<std::uint32_t>& samples_per_pixel) {
  if (!wants_samples_aov(args)) {
    write_image(film, output);
    return;
  }
  ImageLayer layer{"samples.Y", {}};
  layer.values.assign(samples_per_pixel.begin(), samples_per_pixel.end());
  const std::vector<ImageLayer> layers{layer};
  if (lowercase_extension(output) == ".exr") {
    write_image(film, output, layers);
  } else {
    write_image(film, output);
    write_image(film, beside_output(output, ".samples.exr"), layers);
  }
  write_sample_count_png(samples_per_pixel, film.width(), film.height(), beside_output(output, ".samples.png"));
}

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

}  // namespace raylab::cli
