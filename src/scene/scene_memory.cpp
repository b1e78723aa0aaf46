#include "raylab/scene/scene_memory.h"

#include <set>
#include <string>
#include <vector>

namespace raylab {
namespace {

// Adds the bytes of `v`'s elements to `used` and its unused capacity to `reserved`.
template <class T>
void count(const std::vector<T>& v, std::size_t& used, std::size_t& reserved) {
  used += v.size() * sizeof(T);
  reserved += (v.capacity() - v.size()) * sizeof(T);
}

// Heap bytes of a string's characters: none while they fit in the string itself.
std::size_t heap_bytes(const std::string& s) { return s.capacity() > std::string().capacity() ? s.capacity() + 1 : 0; }

void count_geometry(const Geometry& g, SceneMemory& m) {
  count(g.triangles, m.geometry, m.reserved);
  count(g.spheres, m.geometry, m.reserved);
  count(g.cylinders, m.geometry, m.reserved);
  count(g.disks, m.geometry, m.reserved);
  count(g.quads, m.geometry, m.reserved);
  count(g.triangle_objects, m.geometry, m.reserved);
  count(g.sphere_objects, m.geometry, m.reserved);
  count(g.cylinder_objects, m.geometry, m.reserved);
  count(g.disk_objects, m.geometry, m.reserved);
  count(g.quad_objects, m.geometry, m.reserved);
  count(g.triangle_normals, m.shading, m.reserved);
  count(g.triangle_uvs, m.shading, m.reserved);
}

}  // namespace

SceneMemory scene_memory(const Scene& scene) {
  SceneMemory m;
  count_geometry(scene.geometry, m);
  for (const Geometry& p : scene.prototypes) count_geometry(p, m);
  count(scene.prototypes, m.geometry, m.reserved);
  count(scene.instances, m.geometry, m.reserved);
  count(scene.objects, m.objects, m.reserved);
  for (const SceneObject& o : scene.objects) m.objects += heap_bytes(o.name);
  count(scene.materials, m.materials, m.reserved);
  std::set<const TextureImage*> images;
  for (const Material& mat : scene.materials) {
    m.materials += heap_bytes(mat.name);
    const MaterialMaps& maps = mat.maps;
    for (const TextureImage* image : {mat.texture.image.get(), maps.metallic_roughness.get(), maps.emission.get(),
                                      maps.transmission.get(), maps.normal.get(), maps.bump.get()}) {
      if (image != nullptr && images.insert(image).second) {
        m.textures += sizeof(TextureImage) + static_cast<std::size_t>(image->width()) * image->height() * sizeof(Color);
      }
    }
  }
  count(scene.lights, m.lights, m.reserved);
  return m;
}

}  // namespace raylab
