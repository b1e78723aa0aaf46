// RayQuery: making one, building its structure, and the one-hit-per-ray convenience form.

#include "raylab/query/ray_query.h"

#include <tbb/task_arena.h>

#include "mesh_arrays.h"
#include "ray_query_state.h"
#include "raylab/core/thread_count.h"
#include "raylab/scene/scene_merge.h"

namespace raylab {

RayQuery::RayQuery() : m_state(std::make_unique<State>()) {}
RayQuery::RayQuery(RayQuery&&) noexcept = default;
RayQuery& RayQuery::operator=(RayQuery&&) noexcept = default;
RayQuery::~RayQuery() = default;

// The scene of a mesh given as arrays: its triangles, as object 0 with one default material.
template <class Real>
Scene mesh_scene(std::span<const Real> vertices, std::span<const std::uint32_t> indices) {
  Scene scene;
  scene.geometry = geometry_from_arrays(vertices, indices);
  scene.add_object("mesh", scene.add_material({}));
  return scene;
}

RayQuery RayQuery::from_triangles(std::span<const float> vertices, std::span<const std::uint32_t> indices) {
  return from_scene(mesh_scene(vertices, indices));
}

RayQuery RayQuery::from_triangles(std::span<const double> vertices, std::span<const std::uint32_t> indices) {
  return from_scene(mesh_scene(vertices, indices));
}

RayQuery RayQuery::from_scene(Scene scene) {
  RayQuery query;
  // One flat primitive list: a ray query answers in global ids that a program can look up in
  // geometry(), and the exact all-hits walks run over plain primitives, not nested structures.
  bake_instances(scene);
  scene.instances.clear();
  scene.prototypes.clear();
  query.m_state->scene = std::move(scene);
  return query;
}

void RayQuery::build(std::string_view accel, const AccelConfig& config, int threads) {
  tbb::task_arena arena(usable_threads(threads));
  std::unique_ptr<Accelerator> built;
  arena.execute([&] { built = make_accelerator(accel, m_state->scene.geometry, config); });
  const std::lock_guard lock(m_state->build_mutex);
  m_state->accel = std::move(built);
}

const Accelerator& RayQuery::accelerator() const {
  const std::lock_guard lock(m_state->build_mutex);
  if (!m_state->accel) m_state->accel = make_accelerator("bvh", m_state->scene.geometry);
  return *m_state->accel;
}

const Geometry& RayQuery::geometry() const { return m_state->scene.geometry; }

const Scene& RayQuery::scene() const { return m_state->scene; }

std::vector<QueryHit> RayQuery::intersect(std::span<const Ray> rays, const QueryOptions& options) const {
  std::vector<QueryHit> hits(rays.size());
  std::vector<float> t(rays.size()), uv(rays.size() * 2), normal(rays.size() * 3);
  std::vector<std::int32_t> prim(rays.size()), object(rays.size());
  intersect(RayBatch::of(rays), HitArrays{t.data(), prim.data(), object.data(), uv.data(), normal.data()}, options);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    hits[i] = {t[i],      prim[i],       object[i],
               uv[2 * i], uv[2 * i + 1], {normal[3 * i], normal[3 * i + 1], normal[3 * i + 2]}};
  }
  return hits;
}

}  // namespace raylab
