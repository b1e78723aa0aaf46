#include "raylab/io/obj_writer.h"

#include "raylab/core/error.h"
#include "raylab/io/float_text.h"
#include "raylab/io/mtl_writer.h"

namespace raylab {

std::string encode_obj(const Scene& scene, const std::string& mtl_file) {
  const Geometry& g = scene.geometry;
  if (g.size() != g.triangles.size()) throw UsageError("OBJ output needs a triangle-only scene (tessellate first)");
  std::string out = "# written by raylab\n";
  if (!mtl_file.empty()) out += "mtllib " + mtl_file + "\n";
  const std::vector<std::string> material_names = export_material_names(scene);
  const bool normals = !g.triangle_normals.empty();
  const bool uvs = !g.triangle_uvs.empty();
  std::uint32_t current = kInvalidId;
  std::size_t corner = 1;  // OBJ indices start at 1
  for (std::size_t i = 0; i < g.triangles.size(); ++i) {
    const std::uint32_t object = g.triangle_objects[i];
    if (object != current) {
      current = object;
      out += "o " + (object < scene.objects.size() ? scene.objects[object].name : "object") + "\n";
      if (object < scene.objects.size() && scene.objects[object].material < scene.materials.size()) {
        out += "usemtl " + material_names[scene.objects[object].material] + "\n";
      }
    }
    const Triangle& t = g.triangles[i];
    for (const Vec3& p : {t.p0, t.p1, t.p2}) append_float_line(out, "v", {p.x, p.y, p.z});
    // A zero shading normal means "geometric"; OBJ has no such thing, so write the geometric one.
    const Vec3 geometric = normalize(triangle_normal(t));
    if (normals) {
      for (const Vec3& n : g.triangle_normals[i]) {
        const Vec3 m = dot(n, n) > 0.f ? n : geometric;
        append_float_line(out, "vn", {m.x, m.y, m.z});
      }
    }
    if (uvs) {
      for (const Vec2& uv : g.triangle_uvs[i]) append_float_line(out, "vt", {uv.x, uv.y});
    }
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      const std::string index = std::to_string(corner + k);
      out += ' ' + index;
      if (uvs || normals) out += '/' + (uvs ? index : std::string());
      if (normals) out += '/' + index;
    }
    out += '\n';
    corner += 3;
  }
  return out;
}

}  // namespace raylab
