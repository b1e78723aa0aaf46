#include "raylab/scene/scene.h"

namespace raylab {

std::uint32_t Scene::add_material(Material m) {
  materials.push_back(std::move(m));
  return static_cast<std::uint32_t>(materials.size() - 1);
}

std::uint32_t Scene::add_object(std::string name, std::uint32_t material) {
  objects.push_back({std::move(name), material});
  return static_cast<std::uint32_t>(objects.size() - 1);
}

namespace {

template <class T>
std::size_t bytes_of(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

}  // namespace

std::size_t Scene::memory_bytes() const {
  const Geometry& g = geometry;
  std::size_t n = bytes_of(g.triangles) + bytes_of(g.spheres) + bytes_of(g.cylinders) + bytes_of(g.disks) +
                  bytes_of(g.quads) + bytes_of(g.triangle_objects) + bytes_of(g.sphere_objects) +
                  bytes_of(g.cylinder_objects) + bytes_of(g.disk_objects) + bytes_of(g.quad_objects) +
                  bytes_of(g.triangle_normals) + bytes_of(g.triangle_uvs);
  n += bytes_of(objects) + bytes_of(materials) + bytes_of(lights);
  for (const SceneObject& o : objects) n += o.name.capacity();
  return n;
}

}  // namespace raylab
