#pragma once
/// \file
/// Embree 3 as the yardstick of `raylab bench`: an Embree scene over the same primitives, traced
/// through Embree's own entry points (rtcIntersect1 / rtcOccluded1, and 16-wide packets with a
/// coherent context), with its build time, its memory and the SAH cost of Embree's binary builder.
///
/// Unlike the `embree` accelerator (embree_accel.h: robust mode, our [tmin, tmax) and tie rules
/// behind the Accelerator interface, for correctness), this is Embree as a user would call it for
/// speed: default scene flags and RTC_BUILD_QUALITY_MEDIUM. A second scene with
/// RTC_SCENE_FLAG_ROBUST (watertight, like ours) is built on request, only to settle hit/miss
/// disagreements on edge rays: the default triangle test can let a ray slip between two triangles.
///
/// Triangles are one Embree triangle geometry (Embree primitive id = our global id); any other
/// primitive (the spheres of spd:balls, cylinders, disks, quads) is Embree user geometry whose
/// callbacks call our own shape tests (Geometry::intersect / occluded), so those primitives cost
/// Embree's traversal plus our shape test.
///
/// Everything here exists whether or not raylab was built with Embree; without it
/// embree_reference_available() is false and constructing an EmbreeReference throws UsageError.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "raylab/accel/bvh.h"
#include "raylab/core/ray.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// True when raylab was built with Embree 3.
bool embree_reference_available();

/// An Embree device with one scene over a Geometry's primitives (rebuilt on demand), and an
/// optional robust scene. Queries are const and safe from many threads at once; builds are not.
class EmbreeReference {
 public:
  /// Creates the device and the geometry buffers (a padded copy of the triangles, shared with
  /// Embree so that a build times the BVH alone, as ours does) and builds the default scene.
  /// `geometry` must outlive this object unchanged and must hold no groups. `isa` restricts
  /// Embree's kernels to one instruction set ("sse2", "sse4.2", "avx", "avx2", "avx512"); empty:
  /// Embree picks the best this CPU has (AVX-512 on the development machine). Throws UsageError
  /// when raylab was built without Embree, std::runtime_error when Embree fails.
  explicit EmbreeReference(const Geometry& geometry, const std::string& isa = "");
  ~EmbreeReference();
  EmbreeReference(const EmbreeReference&) = delete;
  EmbreeReference& operator=(const EmbreeReference&) = delete;

  /// Releases the default scene and builds it afresh (default flags, medium quality); returns the
  /// wall-clock seconds of the build (scene creation, geometry set-up, rtcCommitScene).
  double rebuild();
  /// Bytes Embree holds for the default scene, from the device's memory monitor: what the build
  /// allocated net of what it freed (the BVH with its leaf data; not our shared vertex buffer).
  std::size_t scene_bytes() const;
  /// Number of primitives traced through user geometry (our shape tests); 0 for pure meshes.
  std::size_t user_primitive_count() const;

  /// Builds the RTC_SCENE_FLAG_ROBUST scene (once) used by the `robust` queries.
  void build_robust();

  /// Closest hits, one rtcIntersect1 per ray; `hits[i]` is our Hit (t, global prim id, u, v), or
  /// a default Hit for a miss. Rays are [tmin, tmax) as ours (Embree is given the float below
  /// tmax). `robust` uses the robust scene (build_robust first).
  void intersect1(std::span<const Ray> rays, std::span<Hit> hits, bool robust = false) const;
  /// Any hit, one rtcOccluded1 per ray: `occluded[i]` is 1 or 0.
  void occluded1(std::span<const Ray> rays, std::span<std::uint8_t> occluded, bool robust = false) const;
  /// Converts `rays` into Embree's own records ahead of time (replacing any earlier set), for the
  /// loop a user runs whose rays are already in Embree's layout: filling each record just before
  /// its call costs Embree up to 1.7x (docs/performance.md), which our side, reading a prepared
  /// array of Ray, does not pay. The prepared traces below then time Embree alone. `packets`:
  /// prepare packets of 16 consecutive rays (from ray 0, the last one masked) instead of single
  /// records.
  void prepare(std::span<const Ray> rays, bool packets = false);
  /// Restores the prepared records [begin, end) that a trace consumed (tfar and the hit are
  /// written); to be called outside the clock.
  void reset_prepared(std::size_t begin, std::size_t end) const;
  /// One rtcIntersect1 per prepared record in [begin, end), nothing else.
  void intersect1_prepared(std::size_t begin, std::size_t end) const;
  /// One rtcOccluded1 per prepared record in [begin, end), nothing else.
  void occluded1_prepared(std::size_t begin, std::size_t end) const;
  /// rtcIntersect16 on the prepared packets holding rays [begin, end), with a coherent context
  /// as intersect16; `begin` a multiple of 16.
  void intersect16_prepared(std::size_t begin, std::size_t end) const;
  /// rtcOccluded16 on the prepared packets holding rays [begin, end); `begin` a multiple of 16.
  void occluded16_prepared(std::size_t begin, std::size_t end) const;
  /// The answers of the last prepared closest-hit trace, as intersect1 gives them.
  void prepared_hits(std::span<Hit> hits) const;
  /// The answers of the last prepared any-hit trace, as occluded1 gives them.
  void prepared_occluded(std::span<std::uint8_t> occluded) const;
  /// Closest hits by rtcIntersect16 with a coherent context, 16 consecutive rays per packet (the
  /// last packet masked); same answers as intersect1.
  void intersect16(std::span<const Ray> rays, std::span<Hit> hits) const;
  /// Any hit by rtcOccluded16 with a coherent context, 16 consecutive rays per packet.
  void occluded16(std::span<const Ray> rays, std::span<std::uint8_t> occluded) const;

  /// The SAH cost of Embree's own binary tree over the primitive boxes: rtcBuildBVH with medium
  /// quality, branching factor 2 and the leaf size, leaf block size (as Embree's sahBlockSize,
  /// rounded down to a power of two) and cost constants of `config`, collected
  /// through the builder's callbacks into a BvhTree and priced by sah_cost(tree, config), so the
  /// figure compares directly with sah_cost(build_bvh(geometry, config), config).
  double binary_sah_cost(const BvhConfig& config) const;

 private:
  struct State;
  std::unique_ptr<State> m;
};

}  // namespace raylab
