#pragma once
/// \file
/// The library's one entry point for "here are my triangles (or my scene file), build a
/// structure, answer these rays": closest hits, occlusion, crossing counts and point-inside
/// tests over whole batches, in parallel and deterministic. See docs/library.md.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/accel/factory.h"
#include "raylab/query/ray_batch.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// How a batch runs.
struct QueryOptions {
  /// Worker threads (TBB); 0 = all cores. The answers do not depend on it.
  int threads = 0;
  /// Asked from the calling thread every few tens of thousands of rays; once it answers true
  /// the call stops and throws QueryInterrupted (the outputs then hold a part of the answers).
  /// May be empty. The Python module checks for Ctrl-C here.
  std::function<bool()> should_stop;
};

/// Thrown when QueryOptions::should_stop asked a batch to stop.
class QueryInterrupted : public std::runtime_error {
 public:
  QueryInterrupted() : std::runtime_error("ray query interrupted") {}
};

/// One closest hit, for the convenience form of RayQuery::intersect.
struct QueryHit {
  float t = std::numeric_limits<float>::infinity();  ///< +inf on a miss
  std::int32_t prim_id = -1;                         ///< -1 on a miss
  std::int32_t object_id = -1;                       ///< -1 on a miss
  float u = 0.f, v = 0.f;                            ///< barycentric weights of vertex 1 and 2
  Vec3 normal;                                       ///< unit geometric normal as wound

  /// True when something was hit.
  bool valid() const { return prim_id >= 0; }
};

/// Primitives and the structure built over them, answering batches of rays.
///
///     RayQuery q = RayQuery::from_triangles(vertices, indices);   // or from_scene(load_scene(path))
///     q.build("bvh");                                             // any name of accelerator_names()
///     q.intersect(RayBatch{...}, HitArrays{...});
///
/// Every query is safe to call from several threads at once once built. Rays whose direction
/// is zero or not finite, or whose origin is not finite, miss.
class RayQuery {
 public:
  /// A triangle mesh from flat arrays: `vertices` holds x, y, z per vertex, `indices` three
  /// vertex indices per triangle. Triangle i keeps primitive id i (zero-area triangles too:
  /// they are never hit); every triangle is object 0. The arrays are copied. Throws
  /// std::invalid_argument naming the argument when a size is not a multiple of 3, an index
  /// is out of range, or a vertex coordinate is not finite.
  static RayQuery from_triangles(std::span<const float> vertices, std::span<const std::uint32_t> indices);
  /// The same from double-precision vertices (rounded to float, the precision of the tests).
  static RayQuery from_triangles(std::span<const double> vertices, std::span<const std::uint32_t> indices);
  /// Every primitive of a loaded scene (instances are baked into copies first, so primitive ids
  /// follow the scene's flat order and then each instance's); object ids are the scene's.
  static RayQuery from_scene(Scene scene);

  RayQuery(RayQuery&&) noexcept;
  RayQuery& operator=(RayQuery&&) noexcept;
  ~RayQuery();

  /// Builds (or rebuilds) the structure called `accel` (see accelerator_names()) with `config`.
  /// Throws UsageError listing the valid names for an unknown one. Queries before the first
  /// build use "bvh" with the default configuration, built on first use.
  void build(std::string_view accel = "bvh", const AccelConfig& config = {}, int threads = 0);

  /// The structure answering queries (built with the defaults if nothing was built yet).
  const Accelerator& accelerator() const;
  /// The primitives.
  const Geometry& geometry() const;
  /// The scene the primitives came from (empty but for geometry for from_triangles).
  const Scene& scene() const;

  /// Closest hit of every ray of `rays` in [tmin, tmax), written to `out`.
  void intersect(const RayBatch& rays, const HitArrays& out, const QueryOptions& options = {}) const;
  /// Closest hits of `rays` (their own tmin and tmax), one QueryHit per ray.
  std::vector<QueryHit> intersect(std::span<const Ray> rays, const QueryOptions& options = {}) const;

  /// Whether anything lies on each ray in [tmin, tmax): `occluded[i]` is set to 1 or 0.
  void occluded(const RayBatch& rays, std::uint8_t* occluded, const QueryOptions& options = {}) const;

  /// How many times each ray crosses a primitive in [tmin, tmax): each primitive hit counts
  /// once, and a ray through an edge or vertex shared by two triangles counts one crossing
  /// (the tie rule of intersect_triangle). Exact for the "bvh" and "brute" structures; the
  /// others count two crossings at exactly the same distance as one (Accelerator::all_hits).
  void count_intersections(const RayBatch& rays, std::uint32_t* counts, const QueryOptions& options = {}) const;

  /// Whether each point lies inside the closed surface the primitives make: a ray from the
  /// point crosses it an odd number of times (triangles must form closed surfaces; a point on
  /// the surface may go either way). `points` holds x, y, z per point, `stride` floats apart.
  void contains(const float* points, std::size_t count, std::ptrdiff_t stride, std::uint8_t* inside,
                const QueryOptions& options = {}) const;

 private:
  RayQuery();
  struct State;
  std::unique_ptr<State> m_state;
};

}  // namespace raylab
