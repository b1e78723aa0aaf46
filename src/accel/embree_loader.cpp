// Embree through its module (embree_backend.h), loaded the first time an Embree scene is asked
// for: the `embree` accelerator and EmbreeReference, as embree_accel.h and embree_reference.h
// describe them. Without Embree at build time there is no module, and both say so.

#include <memory>
#include <stdexcept>
#include <string>

#include "../core/sibling_module.h"
#include "embree_backend.h"
#include "raylab/accel/embree_accel.h"
#include "raylab/accel/embree_reference.h"
#include "raylab/core/error.h"

namespace raylab {
namespace {

const EmbreeEntries& embree_entries() {
#if defined(RAYLAB_HAVE_EMBREE)
  return sibling_module_entry<EmbreeEntries>(reinterpret_cast<const void*>(&embree_available), kEmbreeModuleFile,
                                             kEmbreeEntriesSymbol);
#else
  throw UsageError("raylab was built without Embree 3 (install libembree-dev and reconfigure)");
#endif
}

}  // namespace

bool embree_available() {
#if defined(RAYLAB_HAVE_EMBREE)
  return true;
#else
  return false;
#endif
}

bool embree_reference_available() { return embree_available(); }

std::unique_ptr<Accelerator> make_embree_accelerator(const Geometry& geometry, std::span<const std::uint32_t> ids) {
  return embree_entries().make_accelerator(geometry, ids);
}

struct EmbreeReference::State {
  std::unique_ptr<EmbreeReferenceBackend> backend;
};

EmbreeReference::EmbreeReference(const Geometry& geometry, const std::string& isa) : m(std::make_unique<State>()) {
  m->backend.reset(embree_entries().make_reference(geometry, isa));
}
EmbreeReference::~EmbreeReference() = default;
double EmbreeReference::rebuild() { return m->backend->rebuild(); }
std::size_t EmbreeReference::scene_bytes() const { return m->backend->scene_bytes(); }
std::size_t EmbreeReference::user_primitive_count() const { return m->backend->user_primitive_count(); }
void EmbreeReference::build_robust() { m->backend->build_robust(); }
void EmbreeReference::intersect1(std::span<const Ray> rays, std::span<Hit> hits, bool robust) const {
  m->backend->intersect1(rays, hits, robust);
}
void EmbreeReference::occluded1(std::span<const Ray> rays, std::span<std::uint8_t> occluded, bool robust) const {
  m->backend->occluded1(rays, occluded, robust);
}
void EmbreeReference::prepare(std::span<const Ray> rays, bool packets) { m->backend->prepare(rays, packets); }
void EmbreeReference::reset_prepared(std::size_t begin, std::size_t end) const {
  m->backend->reset_prepared(begin, end);
}
void EmbreeReference::intersect1_prepared(std::size_t begin, std::size_t end) const {
  m->backend->intersect1_prepared(begin, end);
}
void EmbreeReference::occluded1_prepared(std::size_t begin, std::size_t end) const {
  m->backend->occluded1_prepared(begin, end);
}
void EmbreeReference::intersect16_prepared(std::size_t begin, std::size_t end) const {
  m->backend->intersect16_prepared(begin, end);
}
void EmbreeReference::occluded16_prepared(std::size_t begin, std::size_t end) const {
  m->backend->occluded16_prepared(begin, end);
}
void EmbreeReference::prepared_hits(std::span<Hit> hits) const { m->backend->prepared_hits(hits); }
void EmbreeReference::prepared_occluded(std::span<std::uint8_t> occluded) const {
  m->backend->prepared_occluded(occluded);
}
void EmbreeReference::intersect16(std::span<const Ray> rays, std::span<Hit> hits) const {
  m->backend->intersect16(rays, hits);
}
void EmbreeReference::occluded16(std::span<const Ray> rays, std::span<std::uint8_t> occluded) const {
  m->backend->occluded16(rays, occluded);
}
double EmbreeReference::binary_sah_cost(const BvhConfig& config) const { return m->backend->binary_sah_cost(config); }

}  // namespace raylab
