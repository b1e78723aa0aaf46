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
#include "raylab/io/checkpoint_file.h"
#include "raylab/render/film.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/scene.h"

namespace raylab::cli {

/// The command line of `raylab render`, as parsed.
struct RenderArgs {
  std::string scene = "demo";
  const CLI::Option* scene_option = nullptr;  ///< to tell a scene given from the default
  std::string output = "render.png";
  std::optional<int> width, height, spp, max_depth;
  std::optional<std::uint64_t> seed;
  std::optional<std::string> sampler, filter;
  std::optional<float> filter_radius, aa_threshold;
  std::optional<int> aa_depth;
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

/// A hash of everything that decides the image: every rank of a distributed render must agree.
std::uint64_t render_agreement(const RenderSetup& setup);

/// OUTPUT with its extension replaced by `suffix` ("render.png" -> "render.samples.png").
std::string beside_output(const std::string& output, const std::string& suffix);

/// Writes the image to `output`, and the sample-count outputs that --aov samples asks for.
void write_outputs(const RenderArgs& args, const std::string& output, const Film& film,
                   const std::vector<std::uint32_t>& samples_per_pixel);

/// Tells the user what an interrupted render wrote and how to go on (the partial image `output`,
/// the checkpoint, the tiles left).
void print_interrupted(int signal, const std::string& output, const std::string& checkpoint_path,
                       const RenderProgress& progress);

/// Prints a finished render's notices and its non-finite sample warning.
void print_warnings(const RenderResult& result);

/// Removes the checkpoint of a render that has completed (when it saved checkpoints).
void remove_finished_checkpoint(const RenderSetup& setup);

/// Prints ray counts, traversal work, the accelerator and timings (--stats).
void print_stats(const RenderStats& stats, const AccelInfo& info, double seconds);

/// The one-line description of the sampling for the summary ("16 spp jittered").
std::string sampling_summary(const RenderSetup& setup, const RenderResult& result);

}  // namespace raylab::cli
