#pragma once
/// \file
/// `raylab bench`: our accelerator against Embree 3 on exactly the same rays — agreement first
/// (it throws when the two see different worlds), then single-ray and 16-ray-packet throughput,
/// build speed, memory and the SAH cost of both builders, each figure with the ratio ours/Embree.
/// Every figure comes from one run with the two sides interleaved (ours, Embree, ours, ...), so
/// clock and load drift on a shared machine hit both alike (DESIGN.md: compare as ratios in one
/// run). Without Embree, or with `against_embree` off, our side alone is measured.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "raylab/accel/factory.h"
#include "raylab/core/ray.h"
#include "raylab/lab/ray_sets.h"
#include "raylab/scene/light.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// How a benchmark runs.
struct BenchOptions {
  /// Ray kinds to generate and trace, in this order (ignored with `use_file_rays`).
  std::vector<BenchRayKind> kinds = {BenchRayKind::kPrimary, BenchRayKind::kShadow, BenchRayKind::kDiffuse};
  int threads = 0;             ///< threads for both sides, builds and tracing; 0 = all cores
  int repeats = 5;             ///< timed runs of each figure; the median is reported
  int width = 1024;            ///< primary rays per row
  int height = 768;            ///< rows of primary rays
  bool against_embree = true;  ///< also measure Embree (when raylab was built with it)
  std::string embree_isa;      ///< Embree's instruction set ("avx2", ...); empty: Embree's choice
  std::string accel = "bvh";   ///< our structure, by factory name
  AccelConfig accel_config;    ///< its parameters; `bvh` also prices both binary trees
  std::uint64_t seed = 0;      ///< seed of the shadow-ray light samples and the bounce directions
  bool use_file_rays = false;  ///< trace `file_rays` (closest hit, singles and packets) instead of generating
  std::vector<Ray> file_rays;  ///< rays of a .rays file
  std::string file_rays_name;  ///< where they came from, for the report
  std::function<void(const std::string&)> on_progress;  ///< one line per step, for a log
};

/// One figure for both sides. `embree` is 0 when Embree was not measured.
struct BenchFigure {
  double ours = 0.0;
  double embree = 0.0;
  /// ours / embree, or 0 when Embree was not measured.
  double ratio() const { return embree > 0.0 ? ours / embree : 0.0; }
};

/// How far our answers and Embree's agree on one set of rays.
struct BenchAgreement {
  std::size_t same = 0;            ///< same answer (same primitive at the same t, or same occlusion)
  std::size_t ties = 0;            ///< different primitives at the same t, confirmed by testing Embree's
  std::size_t embree_cracks = 0;   ///< Embree's default scene differs but its robust scene agrees with us
  std::size_t disagreements = 0;   ///< everything else: a real difference
  std::vector<std::string> first;  ///< the first few disagreements, ray and both answers
};

/// One traced set of rays.
struct BenchSetReport {
  std::string name;          ///< "primary", "shadow", "diffuse", or "file"
  bool closest = true;       ///< closest hit (intersect) or any hit (occluded)
  bool packets = false;      ///< also traced in packets of 16
  std::size_t rays = 0;      ///< rays in the set
  std::size_t answered = 0;  ///< by us: rays that hit (closest) or were occluded (any hit)
  BenchAgreement single;     ///< single rays, ours against Embree
  BenchAgreement packet;     ///< packets, ours against Embree
  BenchFigure single_mrays;  ///< Mrays/s, one ray at a time (median)
  BenchFigure packet_mrays;  ///< Mrays/s, packets of 16 (median); 0 when not traced in packets
};

/// Everything `run_bench` measured.
struct BenchReport {
  std::string accel;                ///< our structure
  std::string kernels;              ///< the instruction set of our kernels (raylab/core/isa.h)
  std::size_t primitives = 0;       ///< in the scene
  std::size_t triangles = 0;        ///< of which triangles
  std::size_t user_primitives = 0;  ///< traced by Embree through user geometry (our shape tests)
  int width = 0;                    ///< primary-ray image size (0 for file rays)
  int height = 0;
  int threads = 0;                   ///< threads used
  int repeats = 0;                   ///< timed runs per figure
  bool embree = false;               ///< Embree was measured
  std::vector<std::string> notes;    ///< how the light was chosen, what Embree is, why it is absent
  Light light;                       ///< the point light of the shadow rays
  bool light_from_scene = false;     ///< false when placed by the bench (no point light in the scene)
  BenchFigure build_ms;              ///< build time, median of `repeats` fresh builds
  BenchFigure build_mprims;          ///< primitives per second of build, in millions
  BenchFigure bytes_per_triangle;    ///< structure bytes over the scene's primitives
  BenchFigure sah_cost;              ///< SAH cost of the binary trees (build_bvh; Embree's rtcBuildBVH)
  std::vector<BenchSetReport> sets;  ///< in the order traced
  std::string last_set;              ///< name of the last set traced
  std::vector<Ray> last_rays;        ///< its rays, as traced
  std::vector<Hit> last_hits;        ///< our closest hits of them (untimed; also for shadow rays)
};

/// Thrown by run_bench when our accelerator and Embree disagree on some ray (after ties and
/// Embree's edge cracks are set aside): the message gives the counts and the first rays.
class BenchDisagreement : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Runs the benchmark on `scene`. Throws UsageError for a bad option (repeats, threads or size
/// below 1 where required, an unknown accelerator name), BenchDisagreement when the answers differ.
BenchReport run_bench(const Scene& scene, const BenchOptions& options);

/// Builds our structure for the benchmark (which times this call).
using BenchAccelBuilder = std::function<std::unique_ptr<Accelerator>(const Geometry& geometry)>;

/// The same with our structure made by `build` instead of make_accelerator(options.accel, ...);
/// `options.accel` only names it in the report (tests use this to plant a wrong answer).
BenchReport run_bench(const Scene& scene, const BenchOptions& options, const BenchAccelBuilder& build);

/// The point light of the shadow rays: the scene's first point light; else one placed above the
/// scene: at the centre of the bounds, moved along the camera's up vector by half the bounds'
/// extent along it plus one bounds diagonal. `from_scene` says which.
Light bench_light(const Scene& scene, bool& from_scene);

/// Primary rays through pixel centres in 4x4 tiles: the 16 rays of a tile consecutive (row-major
/// inside the tile), tiles row-major from the top left; tiles at the right and bottom edges are
/// clipped when the size is not a multiple of 4. `pixel`, when given, receives each ray's
/// row-major pixel index. Throws UsageError for a size below 1.
std::vector<Ray> tiled_primary_rays(const Scene& scene, int width, int height,
                                    std::vector<std::uint32_t>* pixel = nullptr);

/// The bench's ray sets: tiled primary rays; shadow rays from their hits (found by `ours`) to
/// `light`; one cosine-weighted diffuse bounce from each hit (see add_secondary_rays).
RaySets make_bench_rays(const Scene& scene, const Accelerator& ours, const Light& light, int width, int height,
                        std::uint64_t seed);

/// The report as an aligned text table with a header and notes.
std::string format_bench_table(const BenchReport& report, const std::string& scene_name);

/// The report as a JSON document.
std::string format_bench_json(const BenchReport& report, const std::string& scene_name);

}  // namespace raylab
