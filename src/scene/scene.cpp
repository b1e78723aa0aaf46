#include "raylab/scene/scene.h"

#include <algorithm>
#include <cmath>

#include "raylab/core/error.h"
#include "raylab/scene/normal_maps.h"
#include "raylab/scene/scene_memory.h"

namespace raylab {

std::uint32_t Scene::add_material(Material m) {
  materials.push_back(std::move(m));
  return static_cast<std::uint32_t>(materials.size() - 1);
}

std::uint32_t Scene::add_object(std::string name, std::uint32_t material) {
  objects.push_back({std::move(name), material});
  return static_cast<std::uint32_t>(objects.size() - 1);
}

std::uint32_t Scene::add_instance(std::uint32_t prototype, const Transform& to_world, std::uint32_t first_object) {
  if (!to_world.valid()) throw UsageError("the transform is not invertible (or not finite)");
  std::uint64_t offset = 0;
  if (!instances.empty()) {
    const Instance& last = instances.back();
    offset = std::uint64_t(last.first_prim_offset) + prototypes[last.prototype].size();
  }
  if (std::uint64_t(geometry.size()) + offset + prototypes[prototype].size() >= kGroupIdBase) {
    throw UsageError("too many primitives: instances would take the scene past 2^31 primitives");
  }
  instances.push_back({prototype, to_world, to_world.inverse(), static_cast<std::uint32_t>(offset), first_object});
  return static_cast<std::uint32_t>(instances.size() - 1);
}

std::uint64_t Scene::primitive_count() const {
  std::uint64_t n = geometry.size();
  for (const Instance& i : instances) n += prototypes[i.prototype].size();
  return n;
}

Box3 Scene::bounds() const {
  Box3 b = geometry.bounds();
  std::vector<Box3> prototype_bounds(prototypes.size());
  for (std::size_t p = 0; p < prototypes.size(); ++p) prototype_bounds[p] = prototypes[p].bounds();
  for (const Instance& i : instances) {
    const Box3& pb = prototype_bounds[i.prototype];
    if (pb.empty()) continue;
    for (int corner = 0; corner < 8; ++corner) {
      b.extend(i.to_world.point(
          {corner & 1 ? pb.hi.x : pb.lo.x, corner & 2 ? pb.hi.y : pb.lo.y, corner & 4 ? pb.hi.z : pb.lo.z}));
    }
  }
  return b;
}

namespace {

// The instance holding global primitive `prim_id` (which must be past the flat primitives).
const Instance& instance_of(const Scene& scene, std::uint32_t prim_id) {
  const std::uint32_t offset = prim_id - scene.geometry.size();
  auto it = std::upper_bound(scene.instances.begin(), scene.instances.end(), offset,
                             [](std::uint32_t o, const Instance& i) { return o < i.first_prim_offset; });
  return *(it - 1);
}

}  // namespace

std::uint32_t Scene::object_of(std::uint32_t prim_id) const {
  if (prim_id < geometry.size()) return geometry.object_of(prim_id);
  const Instance& inst = instance_of(*this, prim_id);
  const std::uint32_t local = prim_id - geometry.size() - inst.first_prim_offset;
  return inst.first_object + prototypes[inst.prototype].object_of(local);
}

namespace {

// surface_at of the scene, the coordinates computed as `coordinates` says (kSkip: a sphere's
// only where the hit's material reads them).
SurfaceInteraction surface_in_scene(const Scene& scene, const Ray& ray, const Hit& hit,
                                    SurfaceCoordinates coordinates) {
  // Only a sphere's coordinates cost more than asking the material whether it reads them (the
  // other shapes' take a few products, a triangle's none); instances' are computed.
  if (coordinates == SurfaceCoordinates::kSkip) {
    const Geometry& g = scene.geometry;
    const bool flat_sphere = hit.prim_id >= g.triangles.size() && hit.prim_id - g.triangles.size() < g.spheres.size();
    if (!flat_sphere || reads_surface_coordinates(scene.material_of(hit.prim_id))) {
      coordinates = SurfaceCoordinates::kCompute;
    }
  }
  if (hit.prim_id < scene.geometry.size()) {
    SurfaceInteraction si = surface_at(scene.geometry, ray, hit, coordinates);
    const MaterialMaps& maps = scene.materials[scene.objects[si.object_id].material].maps;
    if (maps.changes_normal()) {
      if (const std::optional<SurfaceTangents> tangents = surface_tangents(scene.geometry, hit.prim_id))
        apply_normal_maps(maps, *tangents, si);
    }
    return si;
  }
  const Instance& inst = instance_of(scene, hit.prim_id);
  // The same parameter t names the same point in both spaces: the direction is mapped without
  // normalising it.
  Ray local_ray = ray;
  local_ray.origin = inst.to_local.point(ray.origin);
  local_ray.direction = inst.to_local.vector(ray.direction);
  Hit local_hit = hit;
  local_hit.prim_id = hit.prim_id - scene.geometry.size() - inst.first_prim_offset;
  SurfaceInteraction si = surface_at(scene.prototypes[inst.prototype], local_ray, local_hit, coordinates);
  si.position = ray.at(hit.t);
  si.geometric_normal = normalize(inst.to_world.normal(si.geometric_normal));
  si.shading_normal = normalize(inst.to_world.normal(si.shading_normal));
  si.object_id += inst.first_object;
  const MaterialMaps& maps = scene.materials[scene.objects[si.object_id].material].maps;
  if (maps.changes_normal()) {
    if (const std::optional<SurfaceTangents> local =
            surface_tangents(scene.prototypes[inst.prototype], local_hit.prim_id)) {
      apply_normal_maps(maps, {inst.to_world.vector(local->dpdu), inst.to_world.vector(local->dpdv)}, si);
    }
  }
  return si;
}

}  // namespace

SurfaceInteraction surface_at(const Scene& scene, const Ray& ray, const Hit& hit) {
  return surface_in_scene(scene, ray, hit, SurfaceCoordinates::kCompute);
}

SurfaceInteraction shading_surface_at(const Scene& scene, const Ray& ray, const Hit& hit) {
  return surface_in_scene(scene, ray, hit, SurfaceCoordinates::kSkip);
}

std::size_t Scene::memory_bytes() const { return scene_memory(*this).used(); }

}  // namespace raylab
