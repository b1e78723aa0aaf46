#include "raylab/scene/scene_fingerprint.h"

#include <algorithm>
#include <bit>
#include <iterator>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "raylab/core/hash64.h"
#include "raylab/scene/environment.h"

namespace raylab {
namespace {

// Shapes hashed as raw bytes must have no padding, whose bytes are not defined: each of these is
// made of 4-byte floats only.
template <class T, std::size_t kFloats>
constexpr bool packed_floats = std::is_trivially_copyable_v<T> && sizeof(T) == kFloats * sizeof(float);
static_assert(packed_floats<Vec3, 3> && packed_floats<Vec2, 2>);
static_assert(packed_floats<Triangle, 9> && packed_floats<Sphere, 4> && packed_floats<Cylinder, 8>);
static_assert(packed_floats<Disk, 7> && packed_floats<Quad, 9>);
static_assert(sizeof(std::array<Vec3, 3>) == 9 * sizeof(float) && sizeof(std::array<Vec2, 3>) == 6 * sizeof(float));

// Hash64 with the scene's value types: lengths go in with every array, so that moving an element
// from one array to the next changes the result.
class Hasher {
 public:
  void word(std::uint64_t w) { m_hash.word(w); }
  void bytes(const void* data, std::size_t n) { m_hash.bytes(data, n); }
  template <class T>
  void array(const std::vector<T>& v) {
    bytes(v.data(), v.size() * sizeof(T));
  }
  void number(float f) { word(std::bit_cast<std::uint32_t>(f)); }
  void number(double d) { word(std::bit_cast<std::uint64_t>(d)); }
  void number(std::uint64_t i) { word(i); }
  void number(int i) { word(static_cast<std::uint64_t>(static_cast<std::int64_t>(i))); }
  void number(bool b) { word(b ? 1u : 0u); }
  void vec(Vec3 v) { bytes(&v, sizeof v); }
  void text(const std::string& s) { bytes(s.data(), s.size()); }
  std::uint64_t value() const { return m_hash.value(); }

 private:
  Hash64 m_hash;
};

void hash_geometry(Hasher& h, const Geometry& g) {
  h.array(g.triangles);
  h.array(g.spheres);
  h.array(g.cylinders);
  h.array(g.disks);
  h.array(g.quads);
  for (const auto* objects :
       {&g.triangle_objects, &g.sphere_objects, &g.cylinder_objects, &g.disk_objects, &g.quad_objects}) {
    h.array(*objects);
  }
  h.array(g.triangle_normals);
  h.array(g.triangle_uvs);
  h.number(static_cast<std::uint64_t>(g.groups.size()));  // scenes hold none; structures make them
}

void hash_image(Hasher& h, const TextureImage& image) {
  h.number(image.width());
  h.number(image.height());
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) h.vec(image.texel(x, y));
  }
}

void hash_material(Hasher& h, const Material& m) {
  h.text(m.name);
  h.vec(m.color);
  for (float f : {m.kd, m.ks, m.shininess, m.reflectivity, m.transmittance, m.ior}) h.number(f);
  h.vec(m.emission);
  h.number(m.fresnel);
  const Texture& t = m.texture;
  h.number(static_cast<int>(t.kind));
  h.vec(t.color2);
  for (float f : {t.scale, t.zone_center.x, t.zone_center.y, t.zone_k, t.zone_radius}) h.number(f);
  h.number(t.image != nullptr);
  if (t.image) hash_image(h, *t.image);
  // The physically based members only where they differ from the defaults, so that the
  // fingerprints of scenes from before they existed (and their checkpoints) stay valid.
  const Material plain;
  if (m.model != plain.model || m.roughness != plain.roughness || m.metallic != plain.metallic ||
      m.transmission != plain.transmission || !(m.conductor_eta == plain.conductor_eta) ||
      !(m.conductor_k == plain.conductor_k) || m.emission_strength != plain.emission_strength) {
    h.number(static_cast<int>(m.model));
    for (float f : {m.roughness, m.metallic, m.transmission, m.emission_strength}) h.number(f);
    h.vec(m.conductor_eta);
    h.vec(m.conductor_k);
  }
  // The maps likewise: only a material that has one hashes them.
  const MaterialMaps& maps = m.maps;
  const std::shared_ptr<const TextureImage>* images[] = {&maps.metallic_roughness, &maps.emission, &maps.transmission,
                                                         &maps.normal, &maps.bump};
  if (std::any_of(std::begin(images), std::end(images), [](const auto* p) { return *p != nullptr; })) {
    h.word(0x4D4150534D415053ull);  // "MAPSMAPS"
    for (const auto* image : images) {
      h.number(*image != nullptr);
      if (*image) hash_image(h, **image);
    }
    h.number(maps.normal_scale);
    h.number(maps.bump_scale);
  }
}

void hash_light(Hasher& h, const Light& l) {
  h.number(static_cast<int>(l.kind));
  for (Vec3 v : {l.position, l.direction, l.edge_u, l.edge_v, l.intensity}) h.vec(v);
  h.number(l.radius);
  h.number(l.falloff);
  h.number(l.samples);
  if (l.object >= 0) h.number(l.object);  // only when set: older fingerprints stay valid
  if (l.kind == Light::Kind::kSpot) {
    h.number(l.spot_angle);
    h.number(l.spot_blend);
  }
}

void hash_environment(Hasher& h, const Environment& e) {
  h.word(0x454E5649524F4E21ull);  // "ENVIRON!": a tag, so that it cannot read as more lights
  h.vec(e.color);
  h.number(e.rotate_degrees);
  h.number(e.scale);
  h.number(e.image != nullptr);
  if (e.image) {
    h.number(e.image->width);
    h.number(e.image->height);
    for (const Color& c : e.image->texels) h.vec(c);
  }
}

void hash_camera(Hasher& h, const CameraSpec& c) {
  for (Vec3 v : {c.from, c.at, c.up}) h.vec(v);
  h.number(c.vfov_degrees);
  h.number(static_cast<int>(c.fov_span));
  h.number(c.hither);
}

// Nothing for a still, so that the fingerprints of stills, and the checkpoints that hold them,
// stay what they were before scenes had paths; a tag word first, so that a path cannot be
// mistaken for more settings.
void hash_camera_path(Hasher& h, const CameraPath& p) {
  if (p.empty()) return;
  h.word(0x43414D5041544821ull);  // "CAMPATH!"
  h.number(static_cast<int>(p.interpolation));
  h.number(static_cast<std::uint64_t>(p.keys.size()));
  for (const CameraKey& k : p.keys) {
    h.number(k.frame);
    hash_camera(h, k.camera);
  }
}

void hash_settings(Hasher& h, const RenderSettings& s) {
  for (int i : {s.width, s.height, s.spp, s.aa_depth, s.max_depth}) h.number(i);
  h.text(s.sampler);
  h.text(s.filter);
  h.number(s.filter_radius);
  h.number(s.aa_threshold);
  h.number(s.seed);
  for (Vec3 c : {s.background, s.horizon, s.ambient}) h.vec(c);
  h.number(s.sky_gradient);
  // Only when not the first integrator, so that fingerprints (and checkpoints) from before the
  // choice existed stay valid.
  if (s.integrator != "whitted") h.text(s.integrator);
}

}  // namespace

std::uint64_t scene_fingerprint(const Scene& scene) {
  Hasher h;
  hash_geometry(h, scene.geometry);
  h.number(static_cast<std::uint64_t>(scene.prototypes.size()));
  for (const Geometry& p : scene.prototypes) hash_geometry(h, p);
  h.number(static_cast<std::uint64_t>(scene.instances.size()));
  for (const Instance& i : scene.instances) {
    h.number(static_cast<std::uint64_t>(i.prototype));
    for (const Transform* t : {&i.to_world, &i.to_local}) {
      for (const auto& row : t->m) {
        for (double d : row) h.number(d);
      }
    }
    h.number(static_cast<std::uint64_t>(i.first_prim_offset));
    h.number(static_cast<std::uint64_t>(i.first_object));
  }
  h.number(static_cast<std::uint64_t>(scene.objects.size()));
  for (const SceneObject& o : scene.objects) {
    h.text(o.name);
    h.number(static_cast<std::uint64_t>(o.material));
  }
  h.number(static_cast<std::uint64_t>(scene.materials.size()));
  for (const Material& m : scene.materials) hash_material(h, m);
  h.number(static_cast<std::uint64_t>(scene.lights.size()));
  for (const Light& l : scene.lights) hash_light(h, l);
  if (scene.environment) hash_environment(h, *scene.environment);  // none: as before there was one
  hash_camera(h, scene.camera);
  h.number(scene.camera_from_file);
  hash_settings(h, scene.settings);
  hash_camera_path(h, scene.camera_path);
  return h.value();
}

}  // namespace raylab
