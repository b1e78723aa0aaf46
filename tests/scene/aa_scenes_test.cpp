// The antialiasing charts: their settings, the pixel calibration of their camera, the exact
// geometry the quality study relies on (star wedges, line widths, edge slopes), the zone-plate
// texture against its formula, and colours traced through the integrator where the answer is
// known exactly.

#include "raylab/scene/aa_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/accel/factory.h"
#include "raylab/render/camera.h"
#include "raylab/render/whitted.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::array<std::string_view, 6> kChartNames = {"aa-checker",    "aa-lines", "aa-zoneplate",
                                                         "aa-highlights", "aa-edges", "aa-whitted"};
constexpr std::array<std::string_view, 4> kPixelCharts = {"aa-lines", "aa-zoneplate", "aa-highlights", "aa-edges"};

bool is_unlit(std::string_view name) {
  return name == "aa-checker" || name == "aa-lines" || name == "aa-zoneplate" || name == "aa-edges";
}

// Traces primary rays through a BVH over one scene, as the renderer does.
class Tracer {
 public:
  explicit Tracer(const Scene& scene)
      : m_scene(scene),
        m_accel(make_accelerator("bvh", scene.geometry)),
        m_camera(scene.camera, scene.settings.width, scene.settings.height) {}

  // Radiance along the camera ray through image position (x, y).
  Color pixel(float x, float y) const { return trace(m_camera.generate(x, y)); }

  // Radiance along the ray from `origin` towards `target`.
  Color towards(Vec3 origin, Vec3 target) const {
    Ray ray;
    ray.origin = origin;
    ray.direction = normalize(target - origin);
    return trace(ray);
  }

  const Camera& camera() const { return m_camera; }

 private:
  Color trace(const Ray& ray) const {
    RenderStats stats;
    const TraceContext ctx{m_scene, *m_accel, stats};
    Pcg32 rng(7);
    return WhittedIntegrator::trace(ctx, ray, 1, RayKind::kPrimary, rng);
  }

  const Scene& m_scene;
  std::unique_ptr<Accelerator> m_accel;
  Camera m_camera;
};

void expect_color_eq(Color got, Color want, const std::string& where) {
  EXPECT_EQ(got.x, want.x) << where;
  EXPECT_EQ(got.y, want.y) << where;
  EXPECT_EQ(got.z, want.z) << where;
}

// The id of the object called `name`; fails the test when there is none.
std::uint32_t object_named(const Scene& scene, std::string_view name) {
  for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
    if (scene.objects[i].name == name) return i;
  }
  ADD_FAILURE() << "no object '" << name << "'";
  return 0;
}

// The primitives of `object` among `primitives`, whose objects are `objects` (one per primitive).
template <class Primitive>
std::vector<Primitive> parts_of(std::uint32_t object, const std::vector<Primitive>& primitives,
                                const std::vector<std::uint32_t>& objects) {
  std::vector<Primitive> parts;
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    if (objects[i] == object) parts.push_back(primitives[i]);
  }
  return parts;
}

// Where a ray meets the plane y = `height` (or z = `height` when `axis` is 2).
Vec3 hit_plane(const Ray& ray, int axis, float height) {
  const float t = (height - ray.origin[axis]) / ray.direction[axis];
  return ray.at(t);
}

// How a unit square of the floor plane y = 0 looks at image position (x, y), in pixels, from
// the Jacobian of the image-to-floor map (central differences).
struct FloorScale {
  double along_x;  // image length of a unit step along world x
  double along_z;  // image length of a unit step along world z
  double side;     // side of the square of the same image area
};

FloorScale floor_scale(const Camera& camera, float x, float y) {
  const Vec3 xp = hit_plane(camera.generate(x + 0.5f, y), 1, 0.f), xm = hit_plane(camera.generate(x - 0.5f, y), 1, 0.f);
  const Vec3 yp = hit_plane(camera.generate(x, y + 0.5f), 1, 0.f), ym = hit_plane(camera.generate(x, y - 0.5f), 1, 0.f);
  const double a = double(xp.x) - xm.x, b = double(yp.x) - ym.x;  // d(world x) / d(px, py)
  const double c = double(xp.z) - xm.z, d = double(yp.z) - ym.z;  // d(world z) / d(px, py)
  const double det = a * d - b * c;
  // The columns of the inverse are the image displacements of unit steps along x and z.
  return {std::hypot(d / det, -c / det), std::hypot(-b / det, a / det), 1.0 / std::sqrt(std::fabs(det))};
}

TEST(AaScenes, EveryChartIsListedBuildsAndHasTheDocumentedSettings) {
  const RenderSettings defaults;
  const auto names = builtin_scene_names();
  for (std::string_view name : kChartNames) {
    SCOPED_TRACE(std::string(name));
    EXPECT_TRUE(is_builtin_scene(name));
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end());
    const Scene scene = make_builtin_scene(name);
    EXPECT_GT(scene.geometry.size(), 0u);
    EXPECT_EQ(scene.settings.width, 640);
    EXPECT_EQ(scene.settings.height, 480);
    EXPECT_EQ(scene.settings.spp, 1);
    EXPECT_EQ(scene.settings.seed, 0u);
    EXPECT_EQ(scene.settings.sampler, defaults.sampler);
    EXPECT_EQ(scene.settings.filter, defaults.filter);
    EXPECT_EQ(scene.settings.max_depth, is_unlit(name) ? 1 : 5);
    EXPECT_TRUE(scene.camera_from_file);
    if (is_unlit(name)) {
      // Pure coverage: every pixel is a coverage-weighted mix of the surfaces' diffuse colours.
      EXPECT_TRUE(scene.lights.empty());
      EXPECT_EQ(scene.settings.ambient.x, 1.f);
      EXPECT_EQ(scene.settings.ambient.y, 1.f);
      EXPECT_EQ(scene.settings.ambient.z, 1.f);
      for (const Material& m : scene.materials) {
        EXPECT_EQ(m.kd, 1.f) << m.name;
        EXPECT_EQ(m.ks, 0.f) << m.name;
        EXPECT_EQ(m.reflectivity, 0.f) << m.name;
        EXPECT_EQ(m.transmittance, 0.f) << m.name;
        EXPECT_EQ(m.emission.x + m.emission.y + m.emission.z, 0.f) << m.name;
      }
    }
  }
}

TEST(AaScenes, PixelCameraMapsThePlaneZ0OntoPixels) {
  EXPECT_EQ(aa_pixel_to_world(10.f, 30.f).y, 450.f);  // image y down, world y up
  for (std::string_view name : kPixelCharts) {
    SCOPED_TRACE(std::string(name));
    const Scene scene = make_builtin_scene(name);
    const Camera camera(scene.camera, scene.settings.width, scene.settings.height);
    const std::array<Vec2, 6> positions{
        {{0.f, 0.f}, {640.f, 480.f}, {320.f, 240.f}, {17.25f, 401.5f}, {612.75f, 33.5f}, {490.3f, 120.6f}}};
    for (const Vec2 p : positions) {
      const Vec3 hit = hit_plane(camera.generate(p.x, p.y), 2, 0.f);
      const Vec3 want = aa_pixel_to_world(p.x, p.y);
      EXPECT_NEAR(hit.x, want.x, 1e-3f) << p.x << ", " << p.y;
      EXPECT_NEAR(hit.y, want.y, 1e-3f) << p.x << ", " << p.y;
    }
  }
}

TEST(AaScenes, ZonePlateTextureFollowsItsFormula) {
  Material m;
  m.color = {1.f, 0.8f, 0.6f};
  const Color c2{0.f, 0.1f, 0.2f};
  const float k = 1.f / 240.f, radius = 180.f;
  m.texture = Texture::zone_plate(c2, {100.f, 50.f}, k, radius);
  const auto at = [&](double r, double angle) {
    return diffuse_color(m, static_cast<float>(100.0 + r * std::cos(angle)),
                         static_cast<float>(50.0 + r * std::sin(angle)));
  };
  // r = 0: the material colour; phase pi (k r^2 = 1): the second colour; phase pi / 2: the mean.
  expect_color_eq(at(0.0, 0.0), m.color, "centre");
  for (double angle : {0.3, 2.0, 4.5}) {
    const Color dark = at(std::sqrt(1.0 / k), angle);
    EXPECT_NEAR(dark.x, c2.x, 1e-5f);
    EXPECT_NEAR(dark.y, c2.y, 1e-5f);
    EXPECT_NEAR(dark.z, c2.z, 1e-5f);
    const Color mid = at(std::sqrt(0.5 / k), angle);
    EXPECT_NEAR(mid.y, 0.45f, 1e-4f);
    // Beyond the rim the flat mean, exactly, whatever the phase would have been.
    for (double r : {180.01, 181.0, 250.0, 1e4}) expect_color_eq(at(r, angle), lerp(c2, m.color, 0.5f), "outside");
  }
  // The local frequency near the rim: successive maxima (k r^2 = 2 m) found by scanning the
  // texture itself, 1e-4 apart, over the last 5 units inside the rim.
  std::vector<double> maxima;
  double prev2 = -1.0, prev1 = -1.0;
  for (double r = radius - 5.0; r <= radius; r += 1e-4) {
    const double value = at(r, 1.0).x;
    if (prev1 >= prev2 && prev1 > value && prev1 > 0.999) maxima.push_back(r - 1e-4);
    prev2 = prev1;
    prev1 = value;
  }
  ASSERT_GE(maxima.size(), 3u);
  const double period = maxima[maxima.size() - 1] - maxima[maxima.size() - 2];
  const double r_mid = 0.5 * (maxima[maxima.size() - 1] + maxima[maxima.size() - 2]);
  EXPECT_NEAR(1.0 / period, k * r_mid, 2e-3);
  EXPECT_NEAR(1.0 / period, 0.75, 0.01);
}

TEST(AaScenes, ZonePlateChartIsCentredAndReachesThreeQuartersOfACyclePerPixel) {
  const Scene scene = make_aa_zoneplate_scene();
  ASSERT_EQ(scene.materials.size(), 1u);
  const Texture& tex = scene.materials[0].texture;
  ASSERT_EQ(tex.kind, Texture::Kind::kZonePlate);
  EXPECT_EQ(tex.zone_radius, 180.f);
  EXPECT_NEAR(double(tex.zone_k) * tex.zone_radius, 0.75, 1e-6);  // cycles per pixel at the rim
  const Tracer tracer(scene);
  const auto grey = [](Color c, float v, float tol, const char* where) {
    EXPECT_NEAR(c.x, v, tol) << where;
    EXPECT_NEAR(c.y, v, tol) << where;
    EXPECT_NEAR(c.z, v, tol) << where;
  };
  grey(tracer.pixel(320.f, 240.f), 1.f, 1e-6f, "centre");
  // Phase pi at r = sqrt(240) px: black (the slope there is 2 pi k r = 0.4 per px).
  grey(tracer.pixel(320.f + std::sqrt(240.f), 240.f), 0.f, 1e-4f, "first dark ring");
  grey(tracer.pixel(320.f, 240.f - std::sqrt(3.f * 240.f)), 0.f, 1e-4f, "second dark ring");
  // Outside the disc, flat 0.5 exactly.
  for (const Vec2 p : {Vec2{5.5f, 5.5f}, Vec2{634.5f, 474.5f}, Vec2{320.f + 182.f, 240.f}, Vec2{30.5f, 240.5f}}) {
    expect_color_eq(tracer.pixel(p.x, p.y), Color(0.5f), "outside the disc");
  }
}

TEST(AaScenes, SiemensStarHas64WedgesOfExactlyHalfAPeriod) {
  const Scene scene = make_aa_lines_scene();
  const std::vector<Triangle> wedges =
      parts_of(object_named(scene, "siemens star"), scene.geometry.triangles, scene.geometry.triangle_objects);
  ASSERT_EQ(wedges.size(), 64u);
  const Vec3 centre = aa_pixel_to_world(kAaStarCenter.x, kAaStarCenter.y);
  const double wedge = 2.0 * kPi / 128.0;
  for (std::size_t i = 0; i < wedges.size(); ++i) {
    const Triangle& t = wedges[i];
    EXPECT_EQ(t.p0.x, centre.x);
    EXPECT_EQ(t.p0.y, centre.y);
    EXPECT_EQ(t.p0.z, 0.f);
    const Vec3 a = t.p1 - t.p0, b = t.p2 - t.p0;
    EXPECT_NEAR(length(a), 120.f, 1e-4f);
    EXPECT_NEAR(length(b), 120.f, 1e-4f);
    // Angles measured as seen in the image (counter-clockwise, with world y up that is atan2).
    const double a0 = std::atan2(double(a.y), double(a.x));
    const double a1 = std::atan2(double(b.y), double(b.x));
    double width = a1 - a0;
    if (width < 0.0) width += 2.0 * kPi;
    EXPECT_NEAR(width, wedge, 1e-5) << "wedge " << i;
    // Wedge i starts a whole period (a wedge and a gap) after wedge i - 1, a quarter wedge
    // off the axes.
    double start = a0 < 0.0 ? a0 + 2.0 * kPi : a0;
    EXPECT_NEAR(start, 0.25 * wedge + 2.0 * kPi * double(i) / 64.0, 1e-5) << "wedge " << i;
  }
}

TEST(AaScenes, ThinLinesSpanTheWidthsAndDirections) {
  const Scene scene = make_aa_lines_scene();
  const std::vector<Quad> quads =
      parts_of(object_named(scene, "thin lines"), scene.geometry.quads, scene.geometry.quad_objects);
  ASSERT_EQ(quads.size(), 25u);
  float min_width = 1e9f, max_width = 0.f;
  std::vector<double> directions;
  for (const Quad& q : quads) {
    const float width = length(q.edge_v);
    min_width = std::min(min_width, width);
    max_width = std::max(max_width, width);
    EXPECT_NEAR(length(q.edge_u), 120.f, 1e-3f);
    EXPECT_NEAR(dot(q.edge_u, q.edge_v), 0.f, 1e-3f);  // rectangles
    double dir = std::atan2(double(q.edge_u.y), double(q.edge_u.x));
    directions.push_back(dir < 0.0 ? dir + kPi : dir);  // modulo 180 degrees
    // Inside the frame with a margin, and clear of the star.
    for (const Vec3 p : {q.corner, q.corner + q.edge_u, q.corner + q.edge_v, q.corner + q.edge_u + q.edge_v}) {
      EXPECT_GT(p.x, 16.f);
      EXPECT_LT(p.x, 640.f - 16.f);
      EXPECT_GT(p.y, 16.f);
      EXPECT_LT(p.y, 480.f - 16.f);
      const Vec3 star = aa_pixel_to_world(kAaStarCenter.x, kAaStarCenter.y);
      EXPECT_GT(length(p - star), kAaStarRadius + 20.f);
    }
  }
  EXPECT_NEAR(min_width, 0.1f, 1e-5f);
  EXPECT_NEAR(max_width, 1.5f, 1e-5f);
  std::sort(directions.begin(), directions.end());
  for (std::size_t i = 1; i < directions.size(); ++i) {
    EXPECT_NEAR(directions[i] - directions[i - 1], 7.2 * kPi / 180.0, 1e-4);  // 25 distinct directions
  }
  for (double d : directions) {  // none along an axis or a diagonal
    EXPECT_GT(std::fabs(std::remainder(d, kPi / 4.0)), 0.5 * kPi / 180.0);
  }
}

TEST(AaScenes, LinesChartColoursAreExactAwayFromEdges) {
  const Scene scene = make_aa_lines_scene();
  const Tracer tracer(scene);
  const Color white(1.f), black(0.f);
  // Middle of wedge 5 and of the gap after it, at 90 px from the star's centre.
  const double wedge = 2.0 * kPi / 128.0;
  for (double mid : {0.25 * wedge + 5 * 2.0 * wedge + 0.5 * wedge, 0.25 * wedge + 5 * 2.0 * wedge + 1.5 * wedge}) {
    const bool in_wedge = mid < 0.25 * wedge + 11.0 * wedge;
    const float x = static_cast<float>(kAaStarCenter.x + 90.0 * std::cos(mid));
    const float y = static_cast<float>(kAaStarCenter.y - 90.0 * std::sin(mid));
    expect_color_eq(tracer.pixel(x, y), in_wedge ? white : black, in_wedge ? "wedge" : "gap");
  }
  // The middle of every line that is at least 0.5 px wide; the margins.
  for (std::size_t i = 0; i < scene.geometry.quads.size(); ++i) {
    const Quad& q = scene.geometry.quads[i];
    if (length(q.edge_v) < 0.5f) continue;
    const Vec3 mid = q.corner + q.edge_u * 0.5f + q.edge_v * 0.5f;
    expect_color_eq(tracer.pixel(mid.x, 480.f - mid.y), white, "line " + std::to_string(i));
  }
  for (const Vec2 p : {Vec2{5.5f, 5.5f}, Vec2{355.5f, 240.5f}, Vec2{634.5f, 474.5f}, Vec2{180.5f, 240.5f}}) {
    expect_color_eq(tracer.pixel(p.x, p.y), black, "background");
  }
}

TEST(AaScenes, EdgesChartHasTheThreeSlopesAtBothContrasts) {
  const Scene scene = make_aa_edges_scene();
  const std::uint32_t high = object_named(scene, "high-contrast shapes");
  const std::uint32_t low = object_named(scene, "low-contrast shapes");
  std::vector<float> slopes;
  const Tracer tracer(scene);
  for (std::size_t i = 0; i < scene.geometry.quads.size(); ++i) {
    const Quad& q = scene.geometry.quads[i];
    const std::uint32_t obj = scene.geometry.quad_objects[i];
    if (obj != high && obj != low) continue;
    EXPECT_EQ(q.corner.z, 0.f);
    EXPECT_GE(length(q.edge_u), 150.f);  // long edges
    if (obj == high) {
      slopes.push_back(q.edge_u.x == 0.f ? INFINITY : std::fabs(q.edge_u.y / q.edge_u.x));
      EXPECT_LT(q.corner.x + std::max(0.f, q.edge_u.x) + std::max(0.f, q.edge_v.x), 320.f - 16.f);
    } else {
      EXPECT_GT(q.corner.x, 320.f + 16.f);
    }
    // Inside the shape, far from its edges: its own colour, exactly.
    const Vec3 mid = q.corner + q.edge_u * 0.5f + q.edge_v * 0.5f;
    expect_color_eq(tracer.pixel(mid.x, 480.f - mid.y), Color(obj == high ? 1.f : 0.55f), "shape centre");
  }
  std::sort(slopes.begin(), slopes.end());
  ASSERT_EQ(slopes.size(), 4u);
  EXPECT_EQ(slopes[0], 0.f);  // the rectangle's long edges are horizontal
  EXPECT_FLOAT_EQ(slopes[1], 0.1f);
  EXPECT_FLOAT_EQ(slopes[2], 1.f);
  EXPECT_FLOAT_EQ(slopes[3], 10.f);
  expect_color_eq(tracer.pixel(10.5f, 470.5f), Color(0.f), "left background");
  expect_color_eq(tracer.pixel(319.5f, 10.5f), Color(0.f), "left of the divide");
  expect_color_eq(tracer.pixel(320.5f, 10.5f), Color(0.5f), "right of the divide");
  expect_color_eq(tracer.pixel(630.5f, 470.5f), Color(0.5f), "right background");
  expect_color_eq(tracer.pixel(639.9f, 0.1f), Color(0.5f), "right corner");
}

TEST(AaScenes, CheckerRunsToTheHorizonAtAThirdWithNearCellsOf30To60Pixels) {
  const Scene scene = make_aa_checker_scene();
  const Tracer tracer(scene);
  const Camera& camera = tracer.camera();
  EXPECT_EQ(scene.camera.from.y, 1.5f);
  // The horizon: the ray through row 160 is horizontal.
  for (float x : {0.f, 320.f, 640.f}) {
    EXPECT_NEAR(camera.generate(x, 160.f).direction.y, 0.f, 1e-6f);
  }
  expect_color_eq(tracer.pixel(320.f, 150.f), kAaCheckerSky, "sky");
  expect_color_eq(tracer.pixel(10.f, 10.f), kAaCheckerSky, "sky corner");
  // Near cells, at the bottom of the image: about 41 px (the side of a square of the same
  // area); seen at 30 degrees, their sides measure 28 to 64 px.
  for (float x : {0.5f, 320.f, 639.5f}) {
    const FloorScale f = floor_scale(camera, x, 479.f);
    EXPECT_GE(f.side * kAaCheckerCell, 30.0) << x;
    EXPECT_LE(f.side * kAaCheckerCell, 60.0) << x;
    EXPECT_GE(std::min(f.along_x, f.along_z) * kAaCheckerCell, 25.0) << x;
    EXPECT_LE(std::max(f.along_x, f.along_z) * kAaCheckerCell, 70.0) << x;
  }
  // Colours, exactly, at positions well inside a cell (the disk's (u, v) is (x, -z)).
  int checked = 0;
  for (float y = 300.5f; y < 480.f; y += 17.f) {
    for (float x = 10.5f; x < 640.f; x += 23.f) {
      const Vec3 p = hit_plane(camera.generate(x, y), 1, 0.f);
      const double cu = p.x / kAaCheckerCell, cv = -p.z / kAaCheckerCell;
      const double fu = cu - std::floor(cu), fv = cv - std::floor(cv);
      if (std::min({fu, 1.0 - fu, fv, 1.0 - fv}) < 0.05) continue;
      const bool even = ((static_cast<long long>(std::floor(cu)) + static_cast<long long>(std::floor(cv))) & 1) == 0;
      expect_color_eq(tracer.pixel(x, y), Color(even ? 1.f : 0.f), "floor");
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
}

TEST(AaScenes, HighlightSpheresEachShowAHighlightTowardsTheCamera) {
  const Scene scene = make_aa_highlights_scene();
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.settings.background.x + scene.settings.background.y + scene.settings.background.z, 0.f);
  const Tracer tracer(scene);
  const Vec3 eye = scene.camera.from;
  const Vec3 light = scene.lights[0].position;
  int shiny = 0, dots = 0;
  std::vector<Vec3> centres;
  for (std::size_t i = 0; i < scene.geometry.spheres.size(); ++i) {
    const Sphere& s = scene.geometry.spheres[i];
    const Material& m = scene.materials[scene.objects[scene.geometry.sphere_objects[i]].material];
    centres.push_back(s.center);
    if (m.ks > 0.f) {
      ++shiny;
      EXPECT_GE(2.f * s.radius, 0.5f - 1e-6f);
      EXPECT_LE(2.f * s.radius, 3.f + 1e-6f);
      EXPECT_EQ(m.ks, 1.f);
      EXPECT_GE(m.shininess, 1000.f - 1e-3f);
      EXPECT_LE(m.shininess, 4000.f + 1e-3f);
      EXPECT_NEAR(m.kd, 0.3f, 1e-6f);
      // The mirror direction of the light: the highlight's peak, on the camera's side.
      const Vec3 n = normalize(normalize(light - s.center) + normalize(eye - s.center));
      const Vec3 peak = s.center + n * s.radius;
      EXPECT_GT(dot(n, normalize(eye - peak)), 0.9f);
      const Color c = tracer.towards(eye, peak);
      EXPECT_GE(std::min({c.x, c.y, c.z}), 0.99f) << "sphere " << i;
      EXPECT_LE(std::max({c.x, c.y, c.z}), 1.5f) << "sphere " << i;
    } else {
      ++dots;
      EXPECT_EQ(m.kd, 0.f);
      EXPECT_GE(2.f * s.radius, 0.2f - 1e-6f);
      EXPECT_LE(2.f * s.radius, 0.8f + 1e-6f);
      EXPECT_LE(std::max({m.emission.x, m.emission.y, m.emission.z}), 1.f);
      expect_color_eq(tracer.towards(eye, s.center), m.emission, "dot " + std::to_string(i));
    }
  }
  EXPECT_GE(shiny, 80);
  EXPECT_LE(shiny, 100);
  EXPECT_EQ(dots, 40);
  // Spread over the frame with dark gaps: every feature 30+ px from every other, all inside.
  for (std::size_t i = 0; i < centres.size(); ++i) {
    EXPECT_GT(centres[i].x, 10.f);
    EXPECT_LT(centres[i].x, 630.f);
    EXPECT_GT(centres[i].y, 10.f);
    EXPECT_LT(centres[i].y, 470.f);
    for (std::size_t j = 0; j < i; ++j) EXPECT_GT(length(centres[i] - centres[j]), 30.f);
  }
  expect_color_eq(tracer.pixel(5.5f, 5.5f), Color(0.f), "background");
}

TEST(AaScenes, WhittedFloorCellsStayWiderThanSixPixels) {
  const Scene scene = make_aa_whitted_scene();
  const Camera camera(scene.camera, scene.settings.width, scene.settings.height);
  const Vec3 forward = normalize(scene.camera.at - scene.camera.from);
  const double pitch = std::asin(-double(forward.y)) * 180.0 / kPi;
  EXPECT_GE(pitch, 25.0);
  EXPECT_LE(pitch, 35.0);
  EXPECT_TRUE(scene.settings.sky_gradient);
  EXPECT_EQ(scene.lights.size(), 2u);
  ASSERT_EQ(scene.geometry.quads.size(), 1u);
  const Box3 floor = scene.geometry.bounds(scene.geometry.size() - 1);  // quads come last
  EXPECT_EQ(floor.hi.x - floor.lo.x, 24.f);
  EXPECT_EQ(floor.hi.z - floor.lo.z, 24.f);
  // Every visible floor position (on a 16 px lattice): cells at least 6 px along both axes.
  double smallest = INFINITY;
  int on_floor = 0;
  for (float y = 8.f; y < 480.f; y += 16.f) {
    for (float x = 8.f; x < 640.f; x += 16.f) {
      const Ray ray = camera.generate(x, y);
      if (ray.direction.y >= 0.f) continue;
      const Vec3 p = hit_plane(ray, 1, 0.f);
      if (!(p.x >= floor.lo.x && p.x <= floor.hi.x && p.z >= floor.lo.z && p.z <= floor.hi.z)) continue;
      ++on_floor;
      const FloorScale f = floor_scale(camera, x, y);
      smallest = std::min({smallest, f.along_x * kAaWhittedCell, f.along_z * kAaWhittedCell});
    }
  }
  EXPECT_GT(on_floor, 600);  // the floor fills the lower part
  EXPECT_GE(smallest, 6.0);  // ... with no cell below 6 px
  // One mirror and one glass sphere, each 100 to 150 px across: the diameter of the disc of
  // the same image area, counted on a 2 px lattice of camera rays.
  int mirrors = 0, glasses = 0;
  for (std::size_t i = 0; i < scene.geometry.spheres.size(); ++i) {
    const Sphere& s = scene.geometry.spheres[i];
    const Material& m = scene.materials[scene.objects[scene.geometry.sphere_objects[i]].material];
    mirrors += m.reflectivity > 0.5f;
    glasses += m.transmittance > 0.5f && m.ior == 1.5f;
    int covered = 0;
    for (float y = 1.f; y < 480.f; y += 2.f) {
      for (float x = 1.f; x < 640.f; x += 2.f) {
        float t = 0.f;
        covered += intersect_sphere(s, camera.generate(x, y), 0.f, INFINITY, t);
      }
    }
    const double across = 2.0 * std::sqrt(4.0 * covered / kPi);
    EXPECT_GE(across, 100.0) << i;
    EXPECT_LE(across, 150.0) << i;
  }
  EXPECT_EQ(mirrors, 1);
  EXPECT_EQ(glasses, 1);
  // Above the floor's far edge: the sky (the horizon colour, since those rays still point down).
  const Tracer tracer(scene);
  expect_color_eq(tracer.pixel(320.f, 120.f), scene.settings.horizon, "beyond the floor");
}

TEST(AaScenes, RadianceStaysBetweenZeroAndOneAndAHalf) {
  for (std::string_view name : kChartNames) {
    SCOPED_TRACE(std::string(name));
    const Scene scene = make_builtin_scene(name);
    const Tracer tracer(scene);
    for (float y = 7.5f; y < 480.f; y += 20.f) {
      for (float x = 9.5f; x < 640.f; x += 20.f) {
        const Color c = tracer.pixel(x, y);
        ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
        EXPECT_GE(std::min({c.x, c.y, c.z}), 0.f);
        EXPECT_LE(std::max({c.x, c.y, c.z}), 1.5f);
      }
    }
  }
}

}  // namespace
}  // namespace raylab
