#include "raylab/io/nff_loader.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/io/read_file.h"
#include "raylab/io/text_scanner.h"

namespace raylab {
namespace {

// The entities this reader knows, for the message about one it does not.
constexpr std::string_view kEntityList =
    "v (view), b (background), l (light), f (fill), c (cone), s (sphere), "
    "p (polygon), pp (polygon patch); '#' starts a comment";

// Fewest bytes one vertex can take in the file: a separator and "0 0 0" (or six numbers for a
// patch vertex). A vertex count larger than the rest of the file can hold is refused before
// any memory is reserved for it, so that "p 1000000000000" cannot exhaust memory.
constexpr std::size_t kMinPolygonVertexBytes = 6;
constexpr std::size_t kMinPatchVertexBytes = 12;
// add_polygon indexes corners with 32-bit integers; no real polygon comes near this.
constexpr std::int64_t kMaxPolygonVertices = std::int64_t{1} << 30;
constexpr std::int64_t kMaxResolution = 65536;

// Names of the three components of a vector, for messages.
struct Names3 {
  std::string_view x, y, z;
};

constexpr Names3 kFrom{"view 'from' x", "view 'from' y", "view 'from' z"};
constexpr Names3 kAt{"view 'at' x", "view 'at' y", "view 'at' z"};
constexpr Names3 kUp{"view 'up' x", "view 'up' y", "view 'up' z"};
constexpr Names3 kBackground{"background red", "background green", "background blue"};
constexpr Names3 kLightPosition{"light x", "light y", "light z"};
constexpr Names3 kFillColor{"fill red", "fill green", "fill blue"};
constexpr Names3 kSphereCenter{"sphere centre x", "sphere centre y", "sphere centre z"};
constexpr Names3 kConeBase{"cone base x", "cone base y", "cone base z"};
constexpr Names3 kConeApex{"cone apex x", "cone apex y", "cone apex z"};
constexpr Names3 kVertex{"polygon vertex x", "polygon vertex y", "polygon vertex z"};
constexpr Names3 kPatchVertex{"patch vertex x", "patch vertex y", "patch vertex z"};
constexpr Names3 kPatchNormal{"patch normal x", "patch normal y", "patch normal z"};

// One pass over the text: tokenizes and validates each entity, then hands it to the builder,
// which owns what the entity means.
class NffParser {
 public:
  NffParser(std::string_view text, const std::string& file, NffSceneBuilder& out)
      : m_text(text), m_in(file, text, '#'), m_out(out) {}

  void run() {
    while (!m_in.at_end()) {
      const Token entity = m_in.next("an entity");
      const std::string_view name = entity.text;
      if (name == "s") {
        sphere();
      } else if (name == "p") {
        polygon(entity, false);
      } else if (name == "pp") {
        polygon(entity, true);
      } else if (name == "c") {
        cone();
      } else if (name == "f") {
        fill();
      } else if (name == "l") {
        light();
      } else if (name == "b") {
        m_out.background(color(kBackground));
      } else if (name == "v") {
        view();
      } else {
        unknown(entity);
      }
    }
  }

 private:
  // The next token as a number that is finite in single precision (1e39 is a finite double but
  // an infinite float, and the scene stores floats). `where` receives the token, for range checks.
  float real(std::string_view what, Token* where = nullptr) {
    const Token t = m_in.next(what);
    if (where != nullptr) *where = t;
    return to_real(t, what);
  }

  float to_real(const Token& t, std::string_view what) const {
    double value = 0.0;
    if (!parse_finite(t.text, value)) {
      m_in.fail(t, "expected " + std::string(what) + " (a finite number), found " + quoted(t.text));
    }
    const float f = static_cast<float>(value);
    if (!std::isfinite(f)) {
      m_in.fail(t, std::string(what) + " " + quoted(t.text) + " is too large for single precision");
    }
    return f;
  }

  float non_negative(std::string_view what) {
    Token t;
    const float value = real(what, &t);
    if (value < 0.f) m_in.fail(t, std::string(what) + " must not be negative, found " + quoted(t.text));
    return value;
  }

  Vec3 vec3(const Names3& names) {
    const float x = real(names.x);
    const float y = real(names.y);
    const float z = real(names.z);
    return {x, y, z};
  }

  Color color(const Names3& names) {
    const float r = non_negative(names.x);
    const float g = non_negative(names.y);
    const float b = non_negative(names.z);
    return {r, g, b};
  }

  // One of the keyword-led lines of the view entity; returns the keyword's token for messages
  // about the values that follow it.
  Token keyword(std::string_view word) {
    const Token t = m_in.next(word);
    if (t.text != word) {
      m_in.fail(t, "expected '" + std::string(word) +
                       "' (the lines of a view entity are from, at, up, angle, hither, resolution, in that "
                       "order), found " +
                       quoted(t.text));
    }
    return t;
  }

  void view() {
    NffView v;
    keyword("from");
    v.from = vec3(kFrom);
    const Token at = keyword("at");
    v.at = vec3(kAt);
    // A camera that looks nowhere or cannot tell up from forward makes NaN rays, not an image.
    if (v.at == v.from) m_in.fail(at, "view 'at' point is the same as the 'from' point");
    const Token up = keyword("up");
    v.up = vec3(kUp);
    const Vec3 side = cross(v.at - v.from, v.up);
    if (!(dot(side, side) > 0.f)) m_in.fail(up, "view 'up' vector is zero or parallel to the viewing direction");
    keyword("angle");
    Token t;
    v.angle = real("view angle", &t);
    if (!(v.angle > 0.0 && v.angle < 180.0)) {
      m_in.fail(t, "view angle must be between 0 and 180 degrees (exclusive), found " + quoted(t.text));
    }
    keyword("hither");
    v.hither = real("view hither distance", &t);
    if (v.hither < 0.0) m_in.fail(t, "view hither distance must not be negative, found " + quoted(t.text));
    keyword("resolution");
    v.xres = static_cast<int>(m_in.integer("image width", 1, kMaxResolution));
    v.yres = static_cast<int>(m_in.integer("image height", 1, kMaxResolution));
    m_out.view(v);
  }

  void light() {
    const Vec3 position = vec3(kLightPosition);
    // The colour is optional; it is present when the light's line goes on.
    const Token red = m_in.next_on_line();
    if (red.text.empty()) {
      m_out.light(position);
      return;
    }
    const float r = to_real(red, "light red");
    if (r < 0.f) m_in.fail(red, "light red must not be negative, found " + quoted(red.text));
    const float g = non_negative("light green");
    const float b = non_negative("light blue");
    m_out.light(position, Color{r, g, b});
  }

  void fill() {
    NffFill f;
    f.color = color(kFillColor);
    f.kd = non_negative("fill Kd");
    f.ks = non_negative("fill Ks");
    f.shine = non_negative("fill shine");
    f.transmittance = non_negative("fill transmittance");
    // Any finite index of refraction is kept: SPD writes 0 for opaque fills, and the builder
    // reads a value <= 0 as "not given".
    f.ior = real("fill index of refraction");
    m_out.fill(f);
  }

  void sphere() {
    const Vec3 center = vec3(kSphereCenter);
    Token t;
    const float radius = real("sphere radius", &t);
    if (!(radius > 0.f)) m_in.fail(t, "sphere radius must be positive, found " + quoted(t.text));
    m_out.sphere(center, radius);
  }

  void cone() {
    const Vec3 base = vec3(kConeBase);
    const float base_radius = non_negative("cone base radius");
    Token apex_token;
    const float ax = real(kConeApex.x, &apex_token);
    const float ay = real(kConeApex.y);
    const float az = real(kConeApex.z);
    const Vec3 apex{ax, ay, az};
    Token t;
    const float apex_radius = real("cone apex radius", &t);
    if (apex_radius < 0.f) m_in.fail(t, "cone apex radius must not be negative, found " + quoted(t.text));
    if (base_radius == 0.f && apex_radius == 0.f) m_in.fail(t, "cone radii are both 0");
    if (apex == base) m_in.fail(apex_token, "cone apex is the same point as its base");
    m_out.cone(base, base_radius, apex, apex_radius);
  }

  void polygon(const Token& entity, bool patch) {
    const std::string_view what = patch ? "patch vertex count" : "polygon vertex count";
    const Token t = m_in.next(what);
    std::string_view digits = t.text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    std::int64_t count = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), count);
    const bool is_integer = !digits.empty() && end == digits.data() + digits.size() &&
                            (ec == std::errc() || ec == std::errc::result_out_of_range);
    if (!is_integer) m_in.fail(t, "expected " + std::string(what) + " (an integer), found " + quoted(t.text));
    // Out of the int64 range is either hugely negative or hugely positive.
    const bool negative = digits.front() == '-';
    const bool huge = ec == std::errc::result_out_of_range;
    if (negative || (!huge && count < 3)) {
      m_in.fail(t, std::string(entity.text) + " needs at least 3 vertices, found " + quoted(t.text));
    }
    const std::size_t per_vertex = patch ? kMinPatchVertexBytes : kMinPolygonVertexBytes;
    const std::size_t remaining = m_text.size() - m_in.offset();
    if (huge || static_cast<std::uint64_t>(count) > remaining / per_vertex) {
      m_in.fail(t, std::string(what) + " " + quoted(t.text) + " is more than the rest of the file can hold (" +
                       std::to_string(remaining) + " bytes, room for at most " +
                       std::to_string(remaining / per_vertex) + " vertices)");
    }
    if (count > kMaxPolygonVertices) {
      m_in.fail(t, std::string(what) + " " + quoted(t.text) + " is more than the limit of " +
                       std::to_string(kMaxPolygonVertices));
    }
    // The buffers keep their capacity from one polygon to the next: no allocation per polygon.
    m_vertices.clear();
    m_normals.clear();
    m_vertices.reserve(static_cast<std::size_t>(count));
    if (patch) m_normals.reserve(static_cast<std::size_t>(count));
    for (std::int64_t i = 0; i < count; ++i) {
      m_vertices.push_back(vec3(patch ? kPatchVertex : kVertex));
      // A zero normal is kept: NFF writers emit them, and shading falls back to the geometric
      // normal for it.
      if (patch) m_normals.push_back(vec3(kPatchNormal));
    }
    if (patch) {
      m_out.patch(m_vertices, m_normals);
    } else {
      m_out.polygon(m_vertices);
    }
  }

  [[noreturn]] void unknown(const Token& entity) const {
    std::string message = "unknown entity " + quoted(entity.text) + "; valid entities are " + std::string(kEntityList);
    double value = 0.0;
    if (parse_finite(entity.text, value)) {
      message += " (a number here often means that the polygon before it has more vertices than its count says)";
    }
    m_in.fail(entity, message);
  }

  std::string_view m_text;
  TextScanner m_in;
  NffSceneBuilder& m_out;
  std::vector<Vec3> m_vertices;
  std::vector<Vec3> m_normals;
};

}  // namespace

void parse_nff(std::string_view text, const std::string& file, NffSceneBuilder& out) {
  NffParser(text, file, out).run();
}

MeshLoadReport load_nff(const std::string& path, Scene& scene) {
  const std::string text = read_file(path);
  NffSceneBuilder builder(scene);
  parse_nff(text, path, builder);
  return builder.finish();
}

}  // namespace raylab
