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
#include "camera_options.h"
#include "command_setup.h"
#include "commands.h"
#include "raylab/accel/factory.h"
#include "raylab/accel/two_level.h"
#include "raylab/core/byte_size.h"
#include "raylab/core/error.h"
#include "raylab/core/interrupt.h"
#include "raylab/core/terminal.h"
#include "raylab/core/text_wrap.h"
#include "raylab/dist/frame_range.h"
#include "raylab/dist/launcher.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/checkpoint_file.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/heatmap.h"
#include "raylab/io/image_io.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/adaptive.h"
#include "raylab/render/integrator.h"
#include "raylab/render/progress.h"
#include "raylab/render/renderer.h"
#include "raylab/render/spd_protocol.h"
#include "raylab/render/spd_protocol_report.h"
#include "raylab/sampling/filter.h"
#include "raylab/sampling/pixel_sampler.h"
#include "raylab/scene/builtin_scenes.h"
#include "raylab/scene/scene_fingerprint.h"
#include "raylab/scene/spd.h"
#include "render_modes.h"
#include "render_report.h"
#include "render_setup.h"

namespace raylab::cli {
namespace {

// One line per scene and generator, wrapped to the terminal with the descriptions hanging.
void list_scenes() {
  const auto width = static_cast<std::size_t>(terminal_columns(STDOUT_FILENO));
  fmt::print("built-in scenes:\n");
  for (const BuiltinScene& b : builtin_scenes()) {
    fmt::print("  {:<14} {}", b.name, wrap_hanging(b.description, width, 17));
  }
  fmt::print("SPD generators (spd:NAME or spd:NAME?size=N):\n");
  for (const SpdGenerator& g : spd_generators()) {
    const std::string text = fmt::format("size 1..{}, default {}: {}", g.max_size, g.default_size, g.description);
    fmt::print("  spd:{:<8} {}", g.name, wrap_hanging(text, width, 15));
  }
  std::string extensions;
  for (auto e : scene_file_extensions()) extensions += (extensions.empty() ? "" : " ") + std::string(e);
  fmt::print("{}", wrap_hanging("scene and mesh files: " + extensions, width, 2));
}

// The SPD testing procedure: the image, the counts as a table (on stderr when the JSON goes to
// stdout, so that stdout stays one JSON document) and as JSON.
int run_spd_protocol(RenderSetup& setup, const RenderOptions& options) {
  const RenderArgs& args = setup.args;
  const ShadowFacing facing = parse_spd_facing(args.spd_facing.value_or("viewer")).value();
  std::optional<SpdSource> source;
  if (is_spd_source(args.scene)) source = parse_spd_source(args.scene);
  const SpdSource* spd = source ? &*source : nullptr;

  Film film(0, 0);  // replaced by the image, which takes over the corners' memory
  const SpdProtocolResult result = render_spd_protocol(setup.scene, *setup.accel, film, options, facing);
  write_image(film, args.output);
  const bool json_stdout = args.json == "-";
  std::FILE* table = json_stdout ? stderr : stdout;
  fmt::print(table, "{}", format_spd_protocol_table(result.counts, facing, spd));
  std::fflush(table);
  if (args.json) {
    const std::string json = format_spd_protocol_json(result, args.scene, facing, spd);
    if (json_stdout) {
      fmt::print("{}", json);
    } else {
      write_text_atomically(*args.json, json);
    }
  }
  if (args.stats) print_stats(result.stats, setup.accel->info(), result.seconds);
  if (!args.quiet) {
    print_summary(fmt::format("wrote {} ({}x{}, SPD protocol, {} rays, --accel {})", args.output, kSpdProtocolSize,
                              kSpdProtocolSize, result.stats.total_rays(), args.accel),
                  result.seconds);
  }
  return 0;
}

std::vector<std::string> sampler_choices() {
  std::vector<std::string> names{"auto"};
  for (auto n : render_sampler_names()) names.emplace_back(n);
  return names;
}

// Usage errors of options that do not go together, before any work.
void check_mode_options(const RenderArgs& given) {
  const SettingsOverride& s = given.settings;
  if (given.spd_protocol && (s.width || s.height || s.spp || s.max_depth)) {
    throw UsageError("--spd-protocol fixes the image size, samples and depth (512x512, corner rays, depth 5)");
  }
  if (given.spd_protocol && (given.passes || given.checkpoint || given.resume || given.frames)) {
    throw UsageError("--spd-protocol renders in one go: no --passes, --checkpoint, --resume or --frames");
  }
  if (!given.spd_protocol && (given.spd_facing || given.json)) {
    throw UsageError(std::string(given.spd_facing ? "--spd-facing" : "--json") + " applies to --spd-protocol only");
  }
  if (given.json && *given.json != "-") check_writable(*given.json);  // fail before the work, not after it
}

// One image in this process.
int render_here(const RenderArgs& given) {
  // Until the render starts there is nothing to save: a signal ends the run at once.
  install_interrupt_handlers(end_at_once, true);
  const std::unique_ptr<RenderSetup> prepared = prepare_render(given, true);
  RenderSetup& setup = *prepared;
  Scene& scene = setup.scene;  // (the SPD protocol sets its own camera settings)
  RenderOptions options = render_options(setup);
  if (setup.args.spd_protocol) return run_spd_protocol(setup, options);
  Film film(scene.settings.width, scene.settings.height);
  std::optional<ProgressBar> bar;
  show_progress(setup.args, options, bar);
  const bool uniform = !is_adaptive_sampler(setup.sampler);
  if (uniform) {
    options.progress = &setup.progress;
    options.should_stop = [] { return interrupt_signal() != 0; };
    write_each_pass(setup, options);
  }
  // From here the first signal lets the tiles under way finish, then the partial image and a
  // checkpoint are written; the adaptive samplers cannot stop part-way, so a signal ends them.
  install_interrupt_handlers(end_at_once, !uniform);
  const RenderResult result = render(scene, *setup.accel, film, options);
  if (result.interrupted) return report_interrupted(setup, film, result, bar, interrupt_signal(), true);
  return report_finished(setup, film, result, bar, nullptr, 1);
}

int run(const RenderArgs& given) {
  if (given.list_scenes) {
    list_scenes();
    return 0;
  }
  check_mode_options(given);
  if (given.frames) return run_frames(given);
  if (dist::launched_by_mpi()) return run_under_mpi(given);
  return render_here(given);
}

// The scene and the image: SCENE, --output, --width, --height.
void add_image_options(CLI::App& cmd, RenderArgs& args) {
  cmd.option_defaults()->group("Scene and output");
  args.scene_option =
      cmd.add_option("scene", args.scene,
                     "Scene: a built-in name (demo, cornell), an SPD generator (spd:balls, spd:balls?size=6), or a "
                     "file (.json .nff .obj .gltf .glb .ply .off .stl); see --list-scenes")
          ->capture_default_str();
  cmd.add_option("-o,--output", args.output, "Output image; format from the extension: .png .exr .pfm")
      ->capture_default_str();
  cmd.add_option("--width", args.settings.width,
                 "Image width in pixels; given alone, the height follows the scene's aspect ratio; both in "
                 "another shape widen the view, never crop it")
      ->check(CLI::Range(1, 32768));
  cmd.add_option("--height", args.settings.height,
                 "Image height in pixels; given alone, the width follows the scene's aspect ratio")
      ->check(CLI::Range(1, 32768));
}

// Where the samples go and how they become pixels: --spp, --sampler, --filter, the adaptive
// samplers' parameters, --aov.
void add_sampling_options(CLI::App& cmd, RenderArgs& args) {
  cmd.option_defaults()->group("Sampling");
  SettingsOverride& s = args.settings;
  cmd.add_option("--spp", s.spp,
                 "Samples per pixel; a count the sampler cannot use is rounded with a notice. Adaptive "
                 "samplers: the most samples a pixel may get (sets --aa-depth to floor(log4 spp))")
      ->check(CLI::Range(1, 1 << 16));
  cmd.add_option("--sampler", s.sampler,
                 "Sample placement: auto (center at 1 spp, else jittered), center, regular, random, jittered, "
                 "cmj, sobol, adaptive-corners, adaptive")
      ->check(CLI::IsMember(sampler_choices()));
  cmd.add_option("--filter", s.filter, "Reconstruction filter: box (default), tent, gaussian, mitchell")
      ->check(CLI::IsMember(std::vector<std::string>(filter_names().begin(), filter_names().end())));
  cmd.add_option("--filter-radius", s.filter_radius,
                 "Filter half-width in pixels (default: box 0.5, tent 1, gaussian 1.5, mitchell 2)")
      ->check(CLI::Range(0.5f, 8.f));
  cmd.add_option("--aa-threshold", s.aa_threshold,
                 "Adaptive samplers: display-encoded colour difference that triggers refinement (default 0.1)")
      ->check(CLI::Range(0.f, 1.f));
  cmd.add_option("--aa-depth", s.aa_depth,
                 "Adaptive samplers: most subdivision levels (a pixel holds at most 4^depth cells)")
      ->check(CLI::Range(0, 8));
  cmd.add_option("--aov", args.aovs,
                 "Extra outputs: 'samples' writes the primary samples per pixel as an EXR layer (into an .exr "
                 "output, else OUTPUT.samples.exr) and a false-colour OUTPUT.samples.png the render's size, with its "
                 "legend in OUTPUT.samples.legend.png")
      ->check(CLI::IsMember({"samples"}))
      ->delimiter(',');
}

// How the rays are traced: --accel and its parameters, --threads, --packets, --seed, --max-depth.
void add_tracing_options(CLI::App& cmd, RenderArgs& args) {
  cmd.option_defaults()->group("Structure and tracing");
  args.accel_option = cmd.add_option("--accel", args.accel, "Acceleration structure")
                          ->check(CLI::IsMember(accelerator_choices()))
                          ->capture_default_str();
  add_accel_parameter_options(cmd, args.structure);
  add_threads_option(cmd, args.threads);
  cmd.add_option("--packets", args.packets,
                 "Trace primary rays in packets of 16 and shadow rays toward point and directional lights as "
                 "one packet per light: on or off. The image and ray counts are identical either way; the "
                 "adaptive samplers always trace single rays")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  // CLI11 (2.1) would read "-1" into the unsigned seed as 2^64 - 1 without a word.
  cmd.add_option("--seed", args.settings.seed, "Seed of every random choice (default: the scene's, 0)")
      ->check([](const std::string& v) { return v.starts_with('-') ? "the seed must not be negative" : ""; });
  cmd.add_option("--max-depth", args.settings.max_depth, "Ray tree depth; 1 = eye rays only (default 5)")
      ->check(CLI::Range(1, 64));
  cmd.add_option("--env", args.settings.environment,
                 "Path integrator: the light from everywhere, a colour R,G,B or a lat-long image (.exr, .pfm; "
                 "docs/rendering.md gives the mapping); replaces the scene's environment");
  cmd.add_option("--env-rotate", args.settings.environment_rotate,
                 "Turn the environment about the up axis by this many degrees (counter-clockwise seen from above)");
  cmd.add_option("--integrator", args.settings.integrator,
                 "What computes the light: whitted (mirror, glass and shadow rays toward the lights; SPD's) or "
                 "path (Monte Carlo path tracing: global illumination); default: the scene's (docs/rendering.md)")
      ->check(CLI::IsMember(std::vector<std::string>(integrator_names().begin(), integrator_names().end())));
}

// Renders that take long or take many: --passes, checkpoints, --max-memory, --frames, MPI.
void add_long_render_options(CLI::App& cmd, RenderArgs& args) {
  cmd.option_defaults()->group("Long renders");
  cmd.add_option("--passes", args.passes,
                 "Take the samples in this many passes over the whole image, writing the image after each "
                 "(uniform samplers; 1 to spp)")
      ->check(CLI::Range(1, 1 << 16));
  cmd.add_option("--checkpoint", args.checkpoint,
                 "Save the render's progress to this file every --checkpoint-every seconds (removed when the "
                 "render completes); an interrupted render always saves one (default: OUTPUT.ckpt)");
  cmd.add_option("--checkpoint-every", args.checkpoint_every, "Seconds between checkpoints")
      ->check(CLI::Range(0.001, 1e9))
      ->capture_default_str();
  cmd.add_option("--resume", args.resume,
                 "Go on with the render saved in this checkpoint (settings not given are taken from it; a "
                 "checkpoint of another scene or other settings is refused); the image is byte-identical to an "
                 "uninterrupted render");
  cmd.add_option("--max-memory", args.max_memory,
                 "Refuse a render whose estimated memory exceeds this (e.g. 512M, 8G; default: 80% of the "
                 "machine's memory)")
      ->check([](const std::string& v) { return parse_byte_size(v) ? "" : "expected a size such as 512M or 8G"; });
  cmd.add_option("--frames", args.frames,
                 "Render frames A to B of the scene's camera path (A:B, or one frame A); OUTPUT gets the "
                 "frame number: a run of # in its name (frame.####.png), else before the extension")
      ->check([](const std::string& v) { return dist::parse_frame_range(v) ? "" : "expected A:B or A (0 <= A <= B)"; });
  cmd.option_defaults()->group("Distributed (MPI)");
  cmd.add_option("--rank-timeout", args.rank_timeout,
                 "Under MPI: seconds a rank holding work may stay silent before the run fails naming it")
      ->check(CLI::Range(0.1, 1e6))
      ->capture_default_str();
}

// What is printed and what is allowed: --stats, --quiet, --allow-outside-paths, --list-scenes;
// then the SPD testing procedure: --spd-protocol, --spd-facing, --json.
void add_report_options(CLI::App& cmd, RenderArgs& args) {
  cmd.option_defaults()->group("Reporting");
  cmd.add_flag("--stats", args.stats, "Print ray counts, traversal work and timings after the render");
  cmd.add_flag("-q,--quiet", args.quiet, "No progress bar and no summary");
  add_allow_outside_paths_flag(cmd, args.allow_outside_paths);
  cmd.add_flag("--list-scenes", args.list_scenes, "List the built-in scenes and SPD generators, then exit");
  cmd.option_defaults()->group("SPD testing procedure");
  cmd.add_flag("--spd-protocol", args.spd_protocol,
               "Render by the SPD testing procedure (512x512, rays through pixel corners, depth 5) and print "
               "the ray counts (beside the SPD README's statistics when the scene is one of its seven at its "
               "size)");
  cmd.add_option("--spd-facing", args.spd_facing,
                 "With --spd-protocol: which normal must face a light for a shadow ray (rule 10): viewer (the "
                 "normal turned toward the ray, default) or outward (the primitive's own)")
      ->check(CLI::IsMember(spd_facing_names()));
  cmd.add_option("--json", args.json,
                 "With --spd-protocol: also write the ray counts as JSON to this file ('-': stdout)");
}

void add_options(CLI::App& cmd, RenderArgs& args) {
  add_image_options(cmd, args);
  add_camera_options(cmd, args.camera);
  add_sampling_options(cmd, args);
  add_tracing_options(cmd, args);
  add_long_render_options(cmd, args);
  add_report_options(cmd, args);
}

}  // namespace

CommandRunner add_render_command(CLI::App& app) {
  return add_command<RenderArgs>(app, "render", "Render a scene to an image (.png, .exr or .pfm)", add_options, run);
}

}  // namespace raylab::cli
