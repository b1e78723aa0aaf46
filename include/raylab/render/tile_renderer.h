#pragma once
/// \file
/// The tiles of a uniform-sampler render, rendered one job at a time on demand: what each process
/// of a distributed render runs, taking its tiles from a coordinator instead of the whole grid.
/// The sums a job produces are the same floats, added in the same order, as render() computes for
/// that tile, so an image assembled from jobs done anywhere has the bits of a local render.

#include <memory>
#include <optional>
#include <string>

#include "raylab/accel/accelerator.h"
#include "raylab/core/stats.h"
#include "raylab/render/render_progress.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// One unit of a uniform-sampler render's work: samples [first, end) of every pixel of one tile,
/// added to the sums the tile holds so far.
struct TileJob {
  int tile = 0;   ///< the tile, numbered as RenderProgress numbers them (row-major from the top-left)
  int first = 0;  ///< index of the first sample of each pixel to take
  int end = 0;    ///< one past the last sample index
  TileSums sums;  ///< before the job: the tile's sums so far; after: with the job's samples added
};

/// Where a TileRenderer's threads take their jobs and hand back finished ones. Both functions are
/// called from several threads at once.
class TileJobSource {
 public:
  virtual ~TileJobSource() = default;
  /// The next job, or nullopt when no more will come; may block until it knows which.
  virtual std::optional<TileJob> next() = 0;
  /// A job whose samples have been added to its sums; `seconds` is the time it took.
  virtual void done(TileJob job, double seconds) = 0;
};

/// Renders jobs of one image (see the file comment) on a pool of threads.
class TileRenderer {
 public:
  /// For `scene` at its settings, traced through `accel` (both must outlive the renderer), with
  /// options.threads threads, options.tile_size tiles, options.packets and
  /// options.count_traversal; the other options are not used. Throws UsageError for an adaptive
  /// sampler (they refine the whole image at once) and for settings render() would refuse.
  TileRenderer(const Scene& scene, const Accelerator& accel, const RenderOptions& options);
  ~TileRenderer();
  TileRenderer(const TileRenderer&) = delete;
  TileRenderer& operator=(const TileRenderer&) = delete;

  /// The state of this render before any sample, in `passes` passes (1 to spp).
  RenderProgress start_progress(int passes) const;
  /// Throws UsageError unless `progress` was made for this image size, tiling, spp and filter.
  void check_progress(const RenderProgress& progress) const;
  /// Takes jobs from `source` on every thread until it answers nullopt to each; returns when
  /// every thread has stopped.
  void run(TileJobSource& source);
  /// The statistics of every job run so far, summed over the threads.
  RenderStats stats();
  /// Worker threads run() uses.
  int threads() const;
  /// Samples per pixel the sampler takes (the settings' spp, rounded where the sampler needs).
  int spp() const;
  /// A line for the user when the spp was rounded, else empty.
  const std::string& notice() const;

 private:
  struct State;
  std::unique_ptr<State> m_state;
};

}  // namespace raylab
