#include "raylab/io/nff_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

namespace raylab {
namespace {

// Disks have no NFF entity; a 32-gon is within 0.5% of the disk's area.
constexpr int kDiskSides = 32;

// The NFF text of one scene, appended to a single string.
class NffWriter {
 public:
  explicit NffWriter(const Scene& scene) : m_scene(scene) {}

  std::string run() {
    const Geometry& g = m_scene.geometry;
    // Rough bytes per entity, so that a megabyte scene is not built by repeated doubling.
    m_out.reserve(512 + 64 * m_scene.lights.size() + 140 * g.triangles.size() + 48 * g.spheres.size() +
                  80 * g.cylinders.size() + 1100 * g.disks.size() + 180 * g.quads.size());
    m_out += "# Neutral File Format (Eric Haines), written by raylab\n";
    view();
    background();
    for (std::size_t i = 0; i < m_scene.lights.size(); ++i) light(m_scene.lights[i]);
    primitives();
    return std::move(m_out);
  }

 private:
  // Appends `v` so that parse_nff, which reads a double and rounds it to float, gets `v` back
  // bit for bit. The shortest float form is read back that way: rounding the decimal to double
  // first could in principle land on the midpoint between two floats, though a sample of 70
  // million floats found no case. The check keeps the guarantee local rather than argued; where
  // it fails, the shortest double form of the same value (which reads back exactly) is written.
  void number(float v) {
    std::array<char, 64> buf;
    auto result = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    if (std::isfinite(v)) {
      double back = 0.0;
      std::from_chars(buf.data(), result.ptr, back);
      if (static_cast<float>(back) != v) {
        result = std::to_chars(buf.data(), buf.data() + buf.size(), static_cast<double>(v));
      }
    }
    m_out.append(buf.data(), result.ptr);
  }

  void integer(long long v) {
    std::array<char, 24> buf;
    const auto result = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    m_out.append(buf.data(), result.ptr);
  }

  // " x y z"
  void vec3(Vec3 v) {
    m_out += ' ';
    number(v.x);
    m_out += ' ';
    number(v.y);
    m_out += ' ';
    number(v.z);
  }

  // A comment line; the text may come from a scene file, so line breaks are taken out.
  void comment(std::string_view text) {
    m_out += "# ";
    for (const char c : text) m_out += (c == '\n' || c == '\r') ? ' ' : c;
    m_out += '\n';
  }

  void view() {
    const CameraSpec& cam = m_scene.camera;
    const int height = m_scene.settings.height;
    float angle = cam.vfov_degrees;
    if (cam.fov_span == CameraSpec::FovSpan::kImageEdges && height > 1) {
      // NFF's angle spans the centres of the first and last pixel rows, (h - 1) pixels of the
      // h that the edge-to-edge field of view spans. (With one row, the camera reads the angle
      // as edge to edge anyway.)
      const double half = static_cast<double>(cam.vfov_degrees) * std::numbers::pi / 360.0;
      const double ratio = static_cast<double>(height - 1) / static_cast<double>(height);
      angle = static_cast<float>(std::atan(std::tan(half) * ratio) * 360.0 / std::numbers::pi);
      comment("angle converted from an edge-to-edge vertical field of view of " + std::to_string(cam.vfov_degrees) +
              " degrees");
    }
    m_out += "v\nfrom";
    vec3(cam.from);
    m_out += "\nat";
    vec3(cam.at);
    m_out += "\nup";
    vec3(cam.up);
    m_out += "\nangle ";
    number(angle);
    m_out += "\nhither ";
    number(cam.hither);
    m_out += "\nresolution ";
    integer(m_scene.settings.width);
    m_out += ' ';
    integer(height);
    m_out += '\n';
  }

  void background() {
    const RenderSettings& s = m_scene.settings;
    if (s.sky_gradient) comment("the background is a gradient towards the horizon colour; NFF keeps one colour");
    if (s.ambient.x != 0.f || s.ambient.y != 0.f || s.ambient.z != 0.f) {
      comment("the scene has an ambient term; NFF has none");
    }
    m_out += 'b';
    vec3(s.background);
    m_out += '\n';
  }

  void light(const Light& l) {
    Vec3 position = l.position;
    switch (l.kind) {
      case Light::Kind::kPoint:
        break;
      case Light::Kind::kDirectional:
        position = distant_position(l.direction);
        comment("directional light approximated by a distant point light");
        break;
      case Light::Kind::kSphere:
        comment("spherical area light approximated by a point light at its centre");
        break;
      case Light::Kind::kQuad:
        position = l.position + (l.edge_u + l.edge_v) * 0.5f;
        comment("quad area light approximated by a point light at its centre");
        break;
    }
    if (l.falloff) comment("the next light falls off with distance; NFF lights do not");
    m_out += 'l';
    vec3(position);
    vec3(l.intensity);
    m_out += '\n';
  }

  // Where a point light stands in for a directional one: far back along the light's direction
  // from the scene's centre, so that its rays arrive nearly parallel everywhere.
  Vec3 distant_position(Vec3 direction) const {
    const Box3 box = m_scene.geometry.bounds();
    Vec3 center{0.f, 0.f, 0.f};
    float radius = 1.f;
    if (!box.empty()) {
      center = box.center();
      radius = std::max(radius, 0.5f * length(box.extent()));
    }
    const float len = length(direction);
    const Vec3 d = len > 0.f ? direction * (1.f / len) : Vec3{0.f, -1.f, 0.f};
    return center - d * (1000.f * radius);
  }

  void fill(const Material& m) {
    if (m.emission.x != 0.f || m.emission.y != 0.f || m.emission.z != 0.f) {
      comment("material '" + m.name + "' emits light; NFF has no emission");
    }
    if (m.texture.kind != Texture::Kind::kNone) {
      comment("material '" + m.name + "' has a texture; NFF keeps its base colour");
    }
    m_out += 'f';
    vec3(m.color);
    m_out += ' ';
    number(m.kd);
    m_out += ' ';
    // NFF's Ks weights both the highlight and the mirror ray.
    number(std::max(m.ks, m.reflectivity));
    m_out += ' ';
    number(m.shininess);
    m_out += ' ';
    number(m.transmittance);
    m_out += ' ';
    number(m.ior);
    m_out += '\n';
  }

  // Indices 0..n-1 ordered by object id, keeping file order within an object. Loaders add
  // primitives object by object, so this is nearly always the identity, and a Scene that came
  // from NFF gets its primitives back in the same order.
  static std::vector<std::uint32_t> order_by_object(const std::vector<std::uint32_t>& objects) {
    std::vector<std::uint32_t> order(objects.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return objects[a] < objects[b]; });
    return order;
  }

  // One primitive kind's primitives in object order, consumed object by object.
  struct Cursor {
    const std::vector<std::uint32_t>* objects;
    std::vector<std::uint32_t> order;
    std::size_t next = 0;

    bool done() const { return next >= order.size(); }
    std::uint32_t object() const { return (*objects)[order[next]]; }
  };

  void primitives() {
    const Geometry& g = m_scene.geometry;
    std::array<Cursor, 5> cursors{Cursor{&g.triangle_objects, order_by_object(g.triangle_objects)},
                                  Cursor{&g.sphere_objects, order_by_object(g.sphere_objects)},
                                  Cursor{&g.cylinder_objects, order_by_object(g.cylinder_objects)},
                                  Cursor{&g.disk_objects, order_by_object(g.disk_objects)},
                                  Cursor{&g.quad_objects, order_by_object(g.quad_objects)}};
    const Material fallback;  // for primitives whose object or material index is out of range
    std::size_t written_material = std::numeric_limits<std::size_t>::max();
    for (;;) {
      // The smallest object id not yet written, over all kinds.
      std::uint32_t object = std::numeric_limits<std::uint32_t>::max();
      bool any = false;
      for (const Cursor& c : cursors) {
        if (!c.done()) {
          object = std::min(object, c.object());
          any = true;
        }
      }
      if (!any) break;
      std::size_t material = m_scene.materials.size();  // stands for `fallback`
      if (object < m_scene.objects.size() && m_scene.objects[object].material < m_scene.materials.size()) {
        material = m_scene.objects[object].material;
      }
      if (material != written_material) {
        fill(material < m_scene.materials.size() ? m_scene.materials[material] : fallback);
        written_material = material;
      }
      for (std::size_t kind = 0; kind < cursors.size(); ++kind) {
        Cursor& c = cursors[kind];
        for (; !c.done() && c.object() == object; ++c.next) primitive(kind, c.order[c.next]);
      }
    }
  }

  void primitive(std::size_t kind, std::uint32_t i) {
    const Geometry& g = m_scene.geometry;
    switch (kind) {
      case 0:
        triangle(i);
        break;
      case 1:
        m_out += 's';
        vec3(g.spheres[i].center);
        m_out += ' ';
        number(g.spheres[i].radius);
        m_out += '\n';
        break;
      case 2: {
        const Cylinder& c = g.cylinders[i];
        m_out += "c\n";
        vec3(c.base);
        m_out += ' ';
        number(c.base_radius);
        m_out += '\n';
        vec3(c.apex);
        m_out += ' ';
        number(c.apex_radius);
        m_out += '\n';
        break;
      }
      case 3:
        disk(g.disks[i]);
        break;
      default: {
        const Quad& q = g.quads[i];
        const std::array<Vec3, 4> corners{q.corner, q.corner + q.edge_u, q.corner + q.edge_u + q.edge_v,
                                          q.corner + q.edge_v};
        m_out += "p 4\n";
        for (const Vec3& p : corners) {
          vec3(p);
          m_out += '\n';
        }
        break;
      }
    }
  }

  void triangle(std::uint32_t i) {
    const Geometry& g = m_scene.geometry;
    const Triangle& t = g.triangles[i];
    const std::array<Vec3, 3> corners{t.p0, t.p1, t.p2};
    // An all-zero set of normals means "none" (Geometry back-fills triangles without normals so).
    const std::array<Vec3, 3>* normals = nullptr;
    if (i < g.triangle_normals.size()) {
      const std::array<Vec3, 3>& n = g.triangle_normals[i];
      const Vec3 zero{0.f, 0.f, 0.f};
      if (!(n[0] == zero && n[1] == zero && n[2] == zero)) normals = &n;
    }
    m_out += normals != nullptr ? "pp 3\n" : "p 3\n";
    for (std::size_t k = 0; k < 3; ++k) {
      vec3(corners[k]);
      if (normals != nullptr) vec3((*normals)[k]);
      m_out += '\n';
    }
  }

  void disk(const Disk& d) {
    const float len = length(d.normal);
    const Vec3 n = len > 0.f ? d.normal * (1.f / len) : Vec3{0.f, 1.f, 0.f};
    // Any unit vector perpendicular to n, and the one perpendicular to both.
    const Vec3 helper = std::abs(n.x) > 0.9f ? Vec3{0.f, 1.f, 0.f} : Vec3{1.f, 0.f, 0.f};
    const Vec3 u = normalize(cross(n, helper));
    const Vec3 v = cross(n, u);
    m_out += "p ";
    integer(kDiskSides);
    m_out += '\n';
    for (int k = 0; k < kDiskSides; ++k) {
      const double a = 2.0 * std::numbers::pi * k / kDiskSides;
      const float c = static_cast<float>(std::cos(a)) * d.radius;
      const float s = static_cast<float>(std::sin(a)) * d.radius;
      vec3(d.center + u * c + v * s);
      m_out += '\n';
    }
  }

  const Scene& m_scene;
  std::string m_out;
};

}  // namespace

std::string encode_nff(const Scene& scene) { return NffWriter(scene).run(); }

}  // namespace raylab
