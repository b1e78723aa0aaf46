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

}  // namespace raylab
