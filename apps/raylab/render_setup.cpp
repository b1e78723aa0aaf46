#include "render_setup.h"

#include <fmt/core.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>

#include "raylab/accel/two_level.h"
#include "raylab/core/byte_size.h"
#include "raylab/core/error.h"
#include "raylab/core/index_ranges.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/checkpoint_resume.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/heatmap.h"
#include "raylab/io/image_io.h"
#include "raylab/io/render_overrides.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/adaptive.h"
#include "raylab/render/memory_limit.h"
#include "raylab/scene/scene_fingerprint.h"

namespace raylab::cli {
namespace {

// Fills what the command line leaves unsaid from the checkpoint being resumed, so that
// `raylab render --resume FILE` alone goes on with the same scene and settings.
void resume_from(RenderArgs& a, const RenderCheckpoint& saved) {
  ResumableRequest request;
  if (a.scene_option->count() != 0) request.scene = a.scene;
  if (a.accel_option->count() != 0) request.accel = a.accel;
  request.passes = a.passes;
  request.settings = a.settings;
  request.camera = a.camera;
  fill_from_checkpoint(request, saved, *a.resume);
  a.scene = *request.scene;
  a.accel = request.accel.value_or(a.accel);
  a.passes = request.passes;
  a.settings = request.settings;
  a.camera = request.camera;
}

bool wants_samples_aov(const RenderArgs& args) {
  return std::find(args.aovs.begin(), args.aovs.end(), "samples") != args.aovs.end();
}

// The image and the sample-count files --aov samples adds.
std::vector<std::string> image_outputs(const RenderArgs& args) {
  std::vector<std::string> files{args.output};
  if (wants_samples_aov(args)) {
    files.push_back(beside_output(args.output, ".samples.png"));
    if (lowercase_extension(args.output) != ".exr") files.push_back(beside_output(args.output, ".samples.exr"));
  }
  return files;
}

// Usage errors about the outputs (an image format, a folder that cannot be written), before any work.
void check_outputs(const RenderArgs& args, bool writes_outputs) {
  check_image_extension(args.output);
  if (!writes_outputs) return;
  for (const std::string& file : image_outputs(args)) check_writable(file);
}

// Usage error when an output of the render would overwrite one of the files the scene was read
// from (the scene file, a mesh, a texture...), once the scene is loaded and before any work.
void check_outputs_not_inputs(const RenderSetup& setup) {
  const std::vector<std::string>& inputs = setup.scene.source_files;
  for (const std::string& file : image_outputs(setup.args)) check_not_an_input(file, inputs);
  check_not_an_input(setup.checkpoint_path, inputs);
  if (setup.args.json && *setup.args.json != "-") check_not_an_input(*setup.args.json, inputs);
}

// Usage errors about the sampling settings `s` (with the resolved `sampler`) and the options that
// only some samplers take, before any work.
void check_sampling(const RenderArgs& args, const RenderSettings& s, const std::string& sampler) {
  if ((args.settings.aa_threshold || args.settings.aa_depth) && !is_adaptive_sampler(sampler)) {
    throw UsageError(
        "--aa-threshold and --aa-depth apply to the adaptive samplers (--sampler adaptive or "
        "adaptive-corners), not to " +
        sampler);
  }
  check_sampling_settings(s);
  const bool long_render = args.passes || args.checkpoint || args.resume;
  if (long_render && is_adaptive_sampler(sampler)) {
    throw UsageError("--passes, --checkpoint and --resume work with the uniform samplers, not with " + sampler +
                     " (its refinement needs the whole image at once)");
  }
}

}  // namespace

std::string beside_output(const std::string& output, const std::string& suffix) {
  const std::filesystem::path p(output);
  return (p.parent_path() / p.stem()).string() + suffix;
}

bool stderr_interactive() { return ::isatty(STDERR_FILENO) != 0; }

void show_progress(const RenderArgs& args, RenderOptions& options, std::optional<ProgressBar>& bar) {
  if (!args.quiet) bar.emplace("render", stderr, stderr_interactive());
  if (bar) options.on_progress = [&bar](int done, int total) { bar->update(done, total); };
}

void write_each_pass(RenderSetup& setup, RenderOptions& options) {
  options.on_pass = [&setup, passes = options.passes, interactive = stderr_interactive()](int done, const Film& image) {
    const RenderArgs& args = setup.args;
    // A whole image of this render (every pixel has the first pass's samples): from here on the
    // output holds this render's image, and an interrupted render may update it in place.
    write_image(image, args.output);
    setup.output_written = true;
    if (!args.quiet) fmt::print(stderr, "{}pass {}/{}: wrote {}\n", interactive ? "\n" : "", done, passes, args.output);
  };
}

void end_at_once() noexcept {
  ProgressBar::end_line_now();
  remove_pending_temporary_files();
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
    resume_from(args, *saved);
  }
  check_outputs(args, writes_outputs);
  std::error_code ec;
  setup.output_existed = writes_outputs && std::filesystem::exists(args.output, ec);
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
  apply_render_overrides(scene, args.settings, args.camera);
  setup.sampler = resolve_sampler_name(s);
  check_sampling(args, s, setup.sampler);
  setup.header =
      RenderCheckpoint{args.scene,
                       fingerprint,
                       image_settings(s, setup.sampler, RenderOptions{}.tile_size, args.passes.value_or(1), args.accel),
                       {}};
  for (auto& camera_part : camera_settings(args.camera)) setup.header.settings.push_back(std::move(camera_part));
  for (auto& env_part : environment_settings(args.settings)) setup.header.settings.push_back(std::move(env_part));
  if (saved) {
    check_resumable(*saved, setup.header, *args.resume);
    setup.progress = std::move(saved->progress);
  }
  // Where checkpoints go: --checkpoint, else the checkpoint resumed, else beside the output (only
  // written if the render is interrupted).
  setup.checkpoint_path = args.checkpoint ? *args.checkpoint
                          : args.resume   ? *args.resume
                                          : beside_output(args.output, ".ckpt");
  if (writes_outputs) {
    check_writable(setup.checkpoint_path);
    check_outputs_not_inputs(setup);
  }
  // Before the accelerator or the image is allocated: refuse what cannot fit (the estimate counts
  // the copies that checkpoints take).
  check_memory_limit(estimate_render_memory(scene, render_options(setup)), scene.primitive_count(),
                     args.max_memory ? parse_byte_size(*args.max_memory) : std::nullopt);

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

}  // namespace raylab::cli
