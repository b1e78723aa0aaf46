#include "raylab/scene/nff_builder.h"

#include <cmath>

namespace raylab {

NffSceneBuilder::NffSceneBuilder(Scene& scene) : m_scene(scene) {
  // NFF scenes are rendered as the SPD testing procedure specifies: ray trees 5 deep.
  m_scene.settings.max_depth = 5;
  m_scene.settings.background = {0.f, 0.f, 0.f};
  m_scene.settings.ambient = {0.f, 0.f, 0.f};
}

void NffSceneBuilder::view(const NffView& view) {
  CameraSpec& cam = m_scene.camera;
  cam.from = view.from;
  cam.at = view.at;
  cam.up = view.up;
  cam.vfov_degrees = static_cast<float>(view.angle);
  cam.fov_span = CameraSpec::FovSpan::kPixelCentres;
  cam.hither = static_cast<float>(view.hither);
  m_scene.settings.width = view.xres;
  m_scene.settings.height = view.yres;
  m_scene.camera_from_file = true;
}

void NffSceneBuilder::background(Color color) { m_scene.settings.background = color; }

void NffSceneBuilder::light(Vec3 position) {
  m_uncoloured_lights.push_back(m_scene.lights.size());
  light(position, Color{1.f, 1.f, 1.f});
}

void NffSceneBuilder::light(Vec3 position, Color color) {
  Light l;
  l.kind = Light::Kind::kPoint;
  l.position = position;
  l.intensity = color;
  l.falloff = false;  // NFF lights do not fall off with distance
  m_scene.lights.push_back(l);
}

void NffSceneBuilder::fill(const NffFill& fill) {
  m_fill = fill;
  m_object = kInvalidId;  // the next primitive starts a new object with this material
  ++m_fill_count;
}

std::uint32_t NffSceneBuilder::current_object() {
  if (m_object != kInvalidId) return m_object;
  Material m;
  m.name = "f" + std::to_string(m_fill_count);
  m.color = m_fill.color;
  m.kd = m_fill.kd;
  m.ks = m_fill.ks;
  m.shininess = m_fill.shine;
  m.reflectivity = m_fill.ks;
  m.transmittance = m_fill.transmittance;
  m.ior = m_fill.ior > 0.f ? m_fill.ior : 1.f;
  // Ks is a mirror share of its own; T is a dielectric interface, which Fresnel splits between a
  // reflected and a refracted ray (the SPD procedure's rules 8 and 9: transmitters reflect too).
  m.fresnel = true;
  const std::uint32_t material = m_scene.add_material(m);
  m_object = m_scene.add_object(m.name, material);
  return m_object;
}

void NffSceneBuilder::sphere(Vec3 center, float radius) {
  m_scene.geometry.add(Sphere{center, radius}, current_object());
}

void NffSceneBuilder::cone(Vec3 base, float base_radius, Vec3 apex, float apex_radius) {
  m_scene.geometry.add(Cylinder{base, base_radius, apex, apex_radius}, current_object());
}

void NffSceneBuilder::polygon(std::span<const Vec3> vertices) {
  m_report.vertices += vertices.size();
  add_polygon(m_scene.geometry, vertices, {}, {}, current_object(), m_report);
}

void NffSceneBuilder::patch(std::span<const Vec3> vertices, std::span<const Vec3> normals) {
  m_report.vertices += vertices.size();
  add_polygon(m_scene.geometry, vertices, normals, {}, current_object(), m_report);
}

MeshLoadReport NffSceneBuilder::finish() {
  if (!m_uncoloured_lights.empty()) {
    const float share = 1.f / std::sqrt(static_cast<float>(m_scene.lights.size()));
    for (const std::size_t i : m_uncoloured_lights) m_scene.lights[i].intensity = Color{share, share, share};
  }
  return m_report;
}

}  // namespace raylab
