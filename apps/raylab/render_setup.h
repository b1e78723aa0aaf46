#pragma once
/// \file
/// `raylab render` before and after the pixels: its arguments, the scene loaded with them, the
/// checkpoint it continues, the outputs and the statistics. Shared by the render of one process
/// (render_command.cpp), of several MPI ranks (render_mpi.cpp) and of animations (render_frames.cpp).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "accel_options.h"
#include "raylab/accel/accelerator.h"
#include "raylab/io/camera_override.h"
#include "raylab/io/checkpoint_file.h"
#include "raylab/render/film.h"
#include "raylab/render/progress.h"
#include "raylab/render/renderer.h"
#include "raylab/render/settings_override.h"
#include "raylab/scene/scene.h"

namespace raylab::cli {

/// The command line of `raylab render`, as parsed.
struct RenderArgs {
  std::string scene = "demo";
  const CLI::Option* scene_option = nullptr;  ///< to tell a scene given from the default
  std::string output = "render.png";
  SettingsOverride settings;  ///< --width, --height, --spp, --max-depth, --seed, --sampler, --filter...
  CameraOverride camera;      ///< --up, --camera-from, --camera-at, --camera-up, --fov, --orbit
  std::vector<std::string> aovs;
  std::string accel = "bvh";
  const CLI::Option* accel_option = nullptr;  ///< to tell --accel given from the default
  AccelArgs structure;
  int threads = 0;
  std::string packets = "on";
  bool stats = false;
  bool quiet = false;
  bool allow_outside_paths = false;
  bool list_scenes = false;
  bool spd_protocol = false;
  std::optional<std::string> spd_facing;  ///< with --spd-protocol: "viewer" or "outward"
  std::optional<std::string> json;        ///< with --spd-protocol: the counts as JSON to this file ('-': stdout)
  std::optional<int> passes;
  std::optional<std::string> checkpoint, resume;
  double checkpoint_every = 60.0;
  std::optional<std::string> max_memory;
  std::optional<std::string> frames;  ///< "A:B" or "A"
  double rank_timeout = 60.0;         ///< under MPI: seconds of silence after which a rank is taken for dead
};

/// A render ready to run: the arguments with what --resume filled in, the scene with the command
/// line's settings applied, the checkpoint header, the state to go on from, the accelerator. It
/// stays where it was made: the accelerator refers to the scene's geometry by address.
struct RenderSetup {
  RenderSetup() = default;
  RenderSetup(const RenderSetup&) = delete;
  RenderSetup& operator=(const RenderSetup&) = delete;

  RenderArgs args;
  Scene scene;
  std::string sampler;          ///< resolved sampler name
  RenderCheckpoint header;      ///< scene name, fingerprint and settings (its progress empty)
  RenderProgress progress;      ///< from --resume, else empty
  std::string checkpoint_path;  ///< where checkpoints go
  std::unique_ptr<Accelerator> accel;
  /// Whether the output was there before the render started (an interrupted render then writes
  /// its partial image beside it), and whether this render has written a whole image of its own
  /// there since (a pass): see partial_image_path.
  bool output_existed = false;
  bool output_written = false;
};

/// Loads and checks everything before the pixels: usage errors (UsageError) and input errors
/// (InputError) come out here, before any work. `writes_outputs`: whether this process writes
/// the image and checkpoints (and so checks that it can). Whether checkpoints will be taken as
/// the render goes (for the memory estimate) follows from the arguments (saves_checkpoints).
std::unique_ptr<RenderSetup> prepare_render(const RenderArgs& given, bool writes_outputs);

/// The RenderOptions of the command line (threads, packets, statistics, passes).
RenderOptions render_options(const RenderSetup& setup);

/// Whether the render saves checkpoints as it goes (--checkpoint or --resume given).
bool saves_checkpoints(const RenderArgs& args);

/// OUTPUT with its extension replaced by `suffix` ("render.png" -> "render.samples.png").
std::string beside_output(const std::string& output, const std::string& suffix);

/// Writes the image to `output`, and the sample-count outputs that --aov samples asks for.
void write_outputs(const RenderArgs& args, const std::string& output, const Film& film,
                   const std::vector<std::uint32_t>& samples_per_pixel);

/// Whether stderr is a terminal (a redrawn progress bar, else summary lines).
bool stderr_interactive();

/// A progress bar for the render on stderr in `bar` (none with --quiet), fed by options.on_progress.
void show_progress(const RenderArgs& args, RenderOptions& options, std::optional<ProgressBar>& bar);

/// Writes the image after each pass of options.passes (set before), with a line saying so, and
/// notes in setup.output_written that the output now holds this render's image.
void write_each_pass(RenderSetup& setup, RenderOptions& options);

/// The last words of a run that a signal ends at once: ends a progress bar's line and removes
/// the temporaries of the writes under way. Async-signal-safe (for install_interrupt_handlers).
void end_at_once() noexcept;

}  // namespace raylab::cli
