#pragma once
// Internal to the render module: how the uniform samplers put a tile's samples into its sums,
// shared by the render loop of one process (renderer.cpp) and by TileRenderer, which renders
// single tiles for a distributed render. Both must add the same floats in the same order, or a
// distributed image would differ from a local one in the last bits.

#include "raylab/render/camera.h"
#include "raylab/render/render_progress.h"
#include "raylab/sampling/filter.h"
#include "raylab/sampling/pixel_sampler.h"
#include "raylab/sampling/sample_dimensions.h"
#include "render_workers.h"

namespace raylab::detail {

/// Whether `f` is the box of half-width 0.5, the plain per-pixel average: no sample leaves its
/// pixel, so no weights are kept.
bool is_pixel_box(const Filter& f);

/// Pixels a tile's samples reach beyond the tile with filter `f` (0 for the pixel box).
int filter_margin(const Filter& f);

/// Throws UsageError unless `p`, a state to go on from, was made for a `width` x `height` image
/// in tiles of `tile_size`, at `spp` samples per pixel, with tiles reaching `margin` pixels out.
void check_resumable(const RenderProgress& p, int width, int height, int tile_size, int spp, int margin);

/// Samples [first, end) of every pixel of tile `rect` added to `sums` (which covers the tile and
/// its margin), in the order of a render in one go: pixels row-major, each pixel's samples in
/// order. A sample's path draws its random numbers from `dims` (made from `sampler`). With
/// `packets`, and an integrator that traces packets, primary and shadow rays are traced in groups
/// (same bits).
void render_tile_samples(const TraceContext& ctx, const Camera& camera, const PixelSampler& sampler,
                         const SampleDimensions& dims, const Filter& filter, bool packets, const PixelRect& rect,
                         int first, int end, TileSums& sums);

}  // namespace raylab::detail
