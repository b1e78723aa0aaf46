#pragma once
/// \file
/// Internal to src/accel: what the Embree module (libraylab_embree: embree_accel.cpp,
/// embree_reference.cpp, embree_module.cpp) gives the library, which loads it the first time an
/// Embree scene is asked for (embree_loader.cpp). Linked into the library, Embree was loaded by
/// every process, about 2.4 ms and 120 page faults each time on the AMD EPYC Zen 5 machine
/// (docs/performance.md, "Page faults on a virtual machine"), though only `--accel embree`,
/// `raylab compare` and `raylab bench` use it.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/bvh.h"
#include "raylab/core/ray.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// EmbreeReference's work (embree_reference.h documents each call): the public class forwards
/// every call to one of these, made by the module.
class EmbreeReferenceBackend {
 public:
  virtual ~EmbreeReferenceBackend() = default;
  /// EmbreeReference::rebuild.
  virtual double rebuild() = 0;
  /// EmbreeReference::scene_bytes.
  virtual std::size_t scene_bytes() const = 0;
  /// EmbreeReference::user_primitive_count.
  virtual std::size_t user_primitive_count() const = 0;
  /// EmbreeReference::build_robust.
  virtual void build_robust() = 0;
  /// EmbreeReference::intersect1.
  virtual void intersect1(std::span<const Ray> rays, std::span<Hit> hits, bool robust) const = 0;
  /// EmbreeReference::occluded1.
  virtual void occluded1(std::span<const Ray> rays, std::span<std::uint8_t> occluded, bool robust) const = 0;
  /// EmbreeReference::prepare.
  virtual void prepare(std::span<const Ray> rays, bool packets) = 0;
  /// EmbreeReference::reset_prepared.
  virtual void reset_prepared(std::size_t begin, std::size_t end) const = 0;
  /// EmbreeReference::intersect1_prepared.
  virtual void intersect1_prepared(std::size_t begin, std::size_t end) const = 0;
  /// EmbreeReference::occluded1_prepared.
  virtual void occluded1_prepared(std::size_t begin, std::size_t end) const = 0;
  /// EmbreeReference::intersect16_prepared.
  virtual void intersect16_prepared(std::size_t begin, std::size_t end) const = 0;
  /// EmbreeReference::occluded16_prepared.
  virtual void occluded16_prepared(std::size_t begin, std::size_t end) const = 0;
  /// EmbreeReference::prepared_hits.
  virtual void prepared_hits(std::span<Hit> hits) const = 0;
  /// EmbreeReference::prepared_occluded.
  virtual void prepared_occluded(std::span<std::uint8_t> occluded) const = 0;
  /// EmbreeReference::intersect16.
  virtual void intersect16(std::span<const Ray> rays, std::span<Hit> hits) const = 0;
  /// EmbreeReference::occluded16.
  virtual void occluded16(std::span<const Ray> rays, std::span<std::uint8_t> occluded) const = 0;
  /// EmbreeReference::binary_sah_cost.
  virtual double binary_sah_cost(const BvhConfig& config) const = 0;
};

/// The module's entry points.
struct EmbreeEntries {
  /// make_embree_accelerator's work.
  std::unique_ptr<Accelerator> (*make_accelerator)(const Geometry& geometry, std::span<const std::uint32_t> ids);
  /// EmbreeReference's constructor's work; the caller owns the result.
  EmbreeReferenceBackend* (*make_reference)(const Geometry& geometry, const std::string& isa);
};

/// In the module: make_accelerator (embree_accel.cpp).
std::unique_ptr<Accelerator> make_embree_accelerator_here(const Geometry& geometry, std::span<const std::uint32_t> ids);
/// In the module: make_reference (embree_reference.cpp).
EmbreeReferenceBackend* make_embree_reference_here(const Geometry& geometry, const std::string& isa);

/// The file name of the module, which lies beside libraylab.
inline constexpr const char* kEmbreeModuleFile = "libraylab_embree.so";
/// The module's one entry point, `const EmbreeEntries* raylab_embree_entries()`.
inline constexpr const char* kEmbreeEntriesSymbol = "raylab_embree_entries";

}  // namespace raylab
