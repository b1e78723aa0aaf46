#include "raylab/io/mtl_writer.h"

#include <algorithm>
#include <map>

#include "raylab/io/float_text.h"

namespace raylab {

std::vector<std::string> export_material_names(const Scene& scene) {
  std::vector<std::string> names;
  std::map<std::string, int> seen;
  names.reserve(scene.materials.size());
  for (const Material& m : scene.materials) {
    std::string name = m.name.empty() ? "material" : m.name;
    std::replace_if(
        name.begin(), name.end(), [](unsigned char c) { return c <= ' '; }, '_');
    const int count = ++seen[name];
    if (count > 1) {
      // The suffixed name may itself be taken ("a~2" written by an earlier conversion).
      std::string candidate;
      for (int k = count;; ++k) {
        candidate = name + "~" + std::to_string(k);
        if (seen.find(candidate) == seen.end()) break;
      }
      ++seen[candidate];
      name = candidate;
    }
    names.push_back(std::move(name));
  }
  return names;
}

std::string encode_mtl(const Scene& scene) {
  const std::vector<std::string> names = export_material_names(scene);
  std::string out = "# written by raylab\n";
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    out += "\nnewmtl " + names[i] + "\n";
    append_float_line(out, "Kd", {m.color.x * m.kd, m.color.y * m.kd, m.color.z * m.kd});
    append_float_line(out, "Ks", {m.ks, m.ks, m.ks});
    append_float_line(out, "Ns", {m.shininess});
    append_float_line(out, "d", {1.f - m.transmittance});
    append_float_line(out, "Tr", {m.transmittance});
    append_float_line(out, "Ni", {m.ior});
    if (m.emission.x != 0.f || m.emission.y != 0.f || m.emission.z != 0.f) {
      append_float_line(out, "Ke", {m.emission.x, m.emission.y, m.emission.z});
    }
    out += m.reflectivity > 0.f ? "illum 3\n" : "illum 2\n";
  }
  return out;
}

}  // namespace raylab
