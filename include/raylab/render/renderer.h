#pragma once
/// \file
/// The tile-parallel render loop.

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/core/stats.h"
#include "raylab/render/film.h"
#include "raylab/render/render_progress.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// How to run a render (settings of the image itself live in Scene::settings).
struct RenderOptions {
  int threads = 0;               ///< worker threads; 0 = all cores
  int tile_size = 16;            ///< square tiles of this many pixels per side
  bool count_traversal = false;  ///< count nodes and primitive tests (slower); see RenderStats
  /// Uniform samplers: trace primary rays in packets of 16 (4x4 pixels at 1 spp, 2x2 pixels x 4
  /// samples at 4 spp, one pixel's samples above) and the shadow rays toward point and directional
  /// lights as one packet per light. The image and the ray counts are the same bits either way;
  /// the adaptive samplers always trace single rays.
  bool packets = true;
  /// Called with (tiles done, tiles total) each time a tile finishes, from whichever worker
  /// finished it (so it must be thread-safe); may be empty. With several passes the totals count
  /// every pass's tiles.
  std::function<void(int, int)> on_progress;
  /// Start the tiles of each pass in a scattered order (scattered_tile_order) rather than row by
  /// row, so that the share of tiles done, which on_progress reports, tracks the share of the
  /// work done (the ETA). The image is the same bits either way; false is for measuring that.
  bool scattered_tiles = true;

  // Long renders (the uniform samplers only; the adaptive samplers refuse these with UsageError).

  /// The samples per pixel are taken in this many passes over the whole image (1 to spp), so
  /// that the image of the first passes can be looked at while the rest renders.
  int passes = 1;
  /// Where the render keeps its state (RenderProgress). Empty (no tiles): the render starts it
  /// with `passes`. Holding work (from a checkpoint): the render goes on from there, with that
  /// state's passes, and gives the same image as a render never stopped; a state made for another
  /// image size, tile size, spp or filter throws UsageError. When null the render keeps its own.
  RenderProgress* progress = nullptr;
  /// Asked before each tile is started; once it answers true no further tile starts, the tiles
  /// under way finish, and render() returns with RenderResult::interrupted set (the film then
  /// shows the samples so far). May be empty.
  std::function<bool()> should_stop;
  /// Called each time a pass finishes but the last, with the number of passes done and the image
  /// so far, from the calling thread between passes. May be empty.
  std::function<void(int, const Film&)> on_pass;
  /// Called at most every `checkpoint_seconds` (when positive) as tiles finish, with a consistent
  /// copy of the state (finished tiles only), from a worker thread, one call at a time; other
  /// workers go on meanwhile. May be empty.
  std::function<void(const RenderProgress&)> on_checkpoint;
  double checkpoint_seconds = 0.0;  ///< see on_checkpoint
};

/// The worker threads a render with `options` uses: options.threads, or with 0 every core this
/// process may run on.
int render_thread_count(const RenderOptions& options);

/// What a finished render reports.
struct RenderResult {
  RenderStats stats;
  double seconds = 0.0;  ///< wall-clock time of the pixel loop
  /// Sample positions whose colour went into each pixel (row-major, width * height). For the
  /// uniform samplers this is spp everywhere; adaptive samplers vary it (corner rays shared by
  /// neighbouring pixels count in each).
  std::vector<std::uint32_t> samples_per_pixel;
  /// Notices for the user (an --spp rounded to what the sampler can use), one line each.
  std::vector<std::string> notices;
  /// True when RenderOptions::should_stop ended the render before every pass was done.
  bool interrupted = false;

  /// Primary rays traced (adaptive samplers trace a varying number).
  std::uint64_t primary_rays() const { return stats.rays[static_cast<int>(RayKind::kPrimary)]; }
};

/// Every sampler a render accepts besides "auto": the uniform ones (pixel_sampler_names) and
/// then the adaptive ones (adaptive_sampler_names), in that order.
std::vector<std::string_view> render_sampler_names();

/// The sampler a render with `settings` uses: settings.sampler, with "auto" resolved (center at
/// 1 sample per pixel, jittered above).
std::string resolve_sampler_name(const RenderSettings& settings);

/// Throws UsageError when `settings` name an unknown sampler or filter, a bad filter radius, or
/// an adaptive sampler with a filter other than the pixel box (adaptive samplers weight by area
/// within the pixel). render() checks this too; callers check first to fail before any work.
void check_sampling_settings(const RenderSettings& settings);

/// What a render will allocate, estimated from the scene's primitive count and settings before
/// anything is allocated, so that an impossible render is refused up front.
struct RenderMemoryEstimate {
  std::uint64_t samples = 0;    ///< width x height x spp: primary samples (adaptive: at most)
  std::size_t image = 0;        ///< the film, the per-pixel sample counts, the encoded output
  std::size_t sums = 0;         ///< the per-tile sums, and the copies checkpoints take of them
  std::size_t accelerator = 0;  ///< the acceleration structure and its build's arrays
  /// Everything above.
  std::size_t total() const { return image + sums + accelerator; }
};

/// Bytes per primitive the estimate allows for an acceleration structure and its build: generous
/// (the wide BVH keeps 60-70 bytes per triangle and its build about as much again; grids and
/// octrees on dense scenes more).
inline constexpr std::size_t kAccelBytesPerPrimitive = 512;

/// The memory a render of `scene` (at its settings) with `options` will need.
RenderMemoryEstimate estimate_render_memory(const Scene& scene, const RenderOptions& options);

/// Renders `scene` with `accel` into `film` (which must match the settings' size). The image is
/// the same for any thread count and tile order: every sample is seeded by its pixel and index.
/// The sampler, filter and adaptive parameters come from scene.settings; unknown names and
/// unsupported combinations (an adaptive sampler with a filter other than the pixel box) throw
/// UsageError.
RenderResult render(const Scene& scene, const Accelerator& accel, Film& film, const RenderOptions& options = {});

}  // namespace raylab
