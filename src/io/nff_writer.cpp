#include "raylab/io/nff_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

#include "raylab/io/float_text.h"

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
  // bit for bit.
  void number(float v) { append_float_text(m_out, v); }

  void integer(long long v) {
    std::array<char, 24> buf;
    const auto result = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    m_out.append(buf.data(), result.ptr);
  }

  // One field of an entity line, after the space that separates it from what comes before.
  void field(float v) {
    m_out += ' ';
    number(v);
  }
  void field(int v) {
    m_out += ' ';
    integer(v);
  }
  void field(Vec3 v) {
    field(v.x);
    field(v.y);
    field(v.z);
  }

  // A line of the file: `head` (an entity's name, or nothing for the vertex lines that follow
  // one), then each of `fields` after a space. Every NFF line is written through here, so that
  // the separators are decided once.
  template <class... Fields>
  void line(std::string_view head, const Fields&... fields) {
    m_out += head;
    (field(fields), ...);
    m_out += '\n';
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
    line("v");
    line("from", cam.from);
    line("at", cam.at);
    line("up", cam.up);
    line("angle", angle);
    line("hither", cam.hither);
    line("resolution", m_scene.settings.width, height);
  }

  void background() {
    const RenderSettings& s = m_scene.settings;
    if (s.sky_gradient) comment("the background is a gradient towards the horizon colour; NFF keeps one colour");
    if (s.ambient.x != 0.f || s.ambient.y != 0.f || s.ambient.z != 0.f) {
      comment("the scene has an ambient term; NFF has none");
    }
    line("b", s.background);
  }

  void light(const Light& l) {
    Vec3 position = l.position;
    switch (l.kind) {
      case Light::Kind::kPoint:
        break;
      case Light::Kind::kSpot:
        comment("spot light approximated by a point light (NFF has no cone)");
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
    line("l", position, l.intensity);
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
    // NFF's Ks weights both the highlight and the mirror ray.
    line("f", m.color, m.kd, std::max(m.ks, m.reflectivity), m.shininess, m.transmittance, m.ior);
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
        line("s", g.spheres[i].center, g.spheres[i].radius);
        break;
      case 2: {
        const Cylinder& c = g.cylinders[i];
        line("c");
        line("", c.base, c.base_radius);
        line("", c.apex, c.apex_radius);
        break;
      }
      case 3:
        disk(g.disks[i]);
        break;
      default: {
        const Quad& q = g.quads[i];
        const std::array<Vec3, 4> corners{q.corner, q.corner + q.edge_u, q.corner + q.edge_u + q.edge_v,
                                          q.corner + q.edge_v};
        line("p", 4);
        for (const Vec3& p : corners) line("", p);
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
    line(normals != nullptr ? "pp" : "p", 3);
    for (std::size_t k = 0; k < 3; ++k) {
      if (normals != nullptr) {
        line("", corners[k], (*normals)[k]);
      } else {
        line("", corners[k]);
      }
    }
  }

  void disk(const Disk& d) {
    const float len = length(d.normal);
    const Vec3 n = len > 0.f ? d.normal * (1.f / len) : Vec3{0.f, 1.f, 0.f};
    // Any unit vector perpendicular to n, and the one perpendicular to both.
    const Vec3 helper = std::abs(n.x) > 0.9f ? Vec3{0.f, 1.f, 0.f} : Vec3{1.f, 0.f, 0.f};
    const Vec3 u = normalize(cross(n, helper));
    const Vec3 v = cross(n, u);
    line("p", kDiskSides);
    for (int k = 0; k < kDiskSides; ++k) {
      const double a = 2.0 * std::numbers::pi * k / kDiskSides;
      const float c = static_cast<float>(std::cos(a)) * d.radius;
      const float s = static_cast<float>(std::sin(a)) * d.radius;
      line("", d.center + u * c + v * s);
    }
  }

  const Scene& m_scene;
  std::string m_out;
};

}  // namespace

std::string encode_nff(const Scene& scene) { return NffWriter(scene).run(); }

}  // namespace raylab
