#include "raylab/scene/scene_merge.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "raylab/core/error.h"

namespace raylab {

std::optional<double> similarity_scale(const Transform& t) {
  // Columns of the linear part must be orthogonal and of equal length.
  double col[3][3];
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) col[c][r] = t.m[r][c];
  auto dotc = [&](int a, int b) { return col[a][0] * col[b][0] + col[a][1] * col[b][1] + col[a][2] * col[b][2]; };
  const double l0 = dotc(0, 0), l1 = dotc(1, 1), l2 = dotc(2, 2);
  const double scale2 = (l0 + l1 + l2) / 3.0;
  if (!(scale2 > 0.0) || !std::isfinite(scale2)) return std::nullopt;
  const double tol = 1e-6 * scale2;
  if (std::abs(l0 - scale2) > tol || std::abs(l1 - scale2) > tol || std::abs(l2 - scale2) > tol) return std::nullopt;
  if (std::abs(dotc(0, 1)) > tol || std::abs(dotc(0, 2)) > tol || std::abs(dotc(1, 2)) > tol) return std::nullopt;
  return std::sqrt(scale2);
}

namespace {

// Throws UsageError when `placement` cannot be applied to `g` (see append_scene).
void check_placement(const Geometry& g, const Transform& placement) {
  if (!placement.valid()) throw UsageError("the transform is not invertible (or not finite)");
  if (!similarity_scale(placement) && (!g.spheres.empty() || !g.cylinders.empty() || !g.disks.empty())) {
    throw UsageError(
        "a transform with non-uniform scale or shear cannot be applied to spheres, cylinders or disks (they stay "
        "analytic); use a uniform scale");
  }
}

// Appends `g` transformed by `placement` (already checked) to `out`, object ids through `object_map`.
void append_geometry(Geometry& out, const Geometry& g, const Transform& placement,
                     const std::vector<std::uint32_t>& object_map) {
  const std::optional<double> scale = similarity_scale(placement);
  const bool mirror = placement.determinant() < 0.0;
  // Without a transform the numbers are kept as they are: re-normalising a shading normal (or
  // turning -0 into +0) would change bits, and a scene written by `raylab convert` must read
  // back to the same image.
  const bool identity = placement.m == Transform::identity().m;
  for (std::size_t i = 0; i < g.triangles.size(); ++i) {
    const Triangle& t = g.triangles[i];
    if (identity) {
      out.add(t, g.triangle_normals.empty() ? nullptr : &g.triangle_normals[i],
              g.triangle_uvs.empty() ? nullptr : &g.triangle_uvs[i], object_map[g.triangle_objects[i]]);
      continue;
    }
    Triangle p{placement.point(t.p0), placement.point(t.p1), placement.point(t.p2)};
    const std::array<Vec3, 3>* normals = nullptr;
    std::array<Vec3, 3> n{};
    if (!g.triangle_normals.empty()) {
      const auto& s = g.triangle_normals[i];
      // A zero normal means "geometric"; keep it zero rather than normalising it.
      for (int k = 0; k < 3; ++k) n[k] = dot(s[k], s[k]) > 0.f ? normalize(placement.normal(s[k])) : Vec3{};
      normals = &n;
    }
    const std::array<Vec2, 3>* uvs = g.triangle_uvs.empty() ? nullptr : &g.triangle_uvs[i];
    std::array<Vec2, 3> uv_copy{};
    if (mirror) {
      // A mirror flips the winding; swap two corners so the outward side stays outward.
      std::swap(p.p1, p.p2);
      std::swap(n[1], n[2]);
      if (uvs) {
        uv_copy = {(*uvs)[0], (*uvs)[2], (*uvs)[1]};
        uvs = &uv_copy;
      }
    }
    out.add(p, normals, uvs, object_map[g.triangle_objects[i]]);
  }
  const float s = scale ? static_cast<float>(*scale) : 1.f;
  for (std::size_t i = 0; i < g.spheres.size(); ++i) {
    out.add(Sphere{placement.point(g.spheres[i].center), g.spheres[i].radius * s}, object_map[g.sphere_objects[i]]);
  }
  for (std::size_t i = 0; i < g.cylinders.size(); ++i) {
    const Cylinder& c = g.cylinders[i];
    out.add(Cylinder{placement.point(c.base), c.base_radius * s, placement.point(c.apex), c.apex_radius * s},
            object_map[g.cylinder_objects[i]]);
  }
  for (std::size_t i = 0; i < g.disks.size(); ++i) {
    const Disk& d = g.disks[i];
    out.add(Disk{placement.point(d.center), normalize(placement.normal(d.normal)), d.radius * s},
            object_map[g.disk_objects[i]]);
  }
  for (std::size_t i = 0; i < g.quads.size(); ++i) {
    const Quad& q = g.quads[i];
    out.add(Quad{placement.point(q.corner), placement.vector(q.edge_u), placement.vector(q.edge_v)},
            object_map[g.quad_objects[i]]);
  }
}

}  // namespace

void append_scene(Scene& dst, const Scene& src, const Transform& placement, std::optional<std::uint32_t> material) {
  check_placement(src.geometry, placement);
  // Objects and materials: remap src ids into dst.
  std::vector<std::uint32_t> material_map(src.materials.size());
  if (!material) {
    for (std::size_t i = 0; i < src.materials.size(); ++i) material_map[i] = dst.add_material(src.materials[i]);
  }
  std::vector<std::uint32_t> object_map(src.objects.size());
  for (std::size_t i = 0; i < src.objects.size(); ++i) {
    const SceneObject& o = src.objects[i];
    object_map[i] = dst.add_object(o.name, material ? *material : material_map[o.material]);
  }
  append_geometry(dst.geometry, src.geometry, placement, object_map);
}

void bake_instances(Scene& scene) {
  for (const Instance& inst : scene.instances) {
    const Geometry& proto = scene.prototypes[inst.prototype];
    check_placement(proto, inst.to_world);
    std::uint32_t objects = 0;
    for (std::uint32_t id = 0; id < proto.size(); ++id) objects = std::max(objects, proto.object_of(id) + 1);
    std::vector<std::uint32_t> object_map(objects);
    for (std::uint32_t k = 0; k < objects; ++k) object_map[k] = inst.first_object + k;
    append_geometry(scene.geometry, proto, inst.to_world, object_map);
  }
  scene.instances.clear();
  scene.prototypes.clear();
}

}  // namespace raylab
