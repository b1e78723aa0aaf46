#pragma once
// Internal to the render module: every light of a scene as the path integrator sees it, and the
// choice among them by power. An emitter is geometry: each emissive triangle, sphere, disk,
// quad, cylinder and cone of the scene's own primitives, and each emissive triangle of an
// instanced mesh, is a light of its own, so that a bounce ray that hits it
// and a shadow ray toward it are two estimates of the same light (combined by MIS).

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "raylab/core/ray.h"
#include "raylab/core/vec3.h"
#include "raylab/geometry/geometry.h"
#include "raylab/render/environment_light.h"
#include "raylab/sampling/distribution.h"
#include "raylab/sampling/pixel_sampler.h"
#include "raylab/scene/scene.h"

namespace raylab::detail {

/// One light sample seen from a shading point.
struct LightSample {
  Vec3 wi;               ///< unit direction toward the light
  float distance = 0.f;  ///< to the light point (infinity for directional and environment light)
  /// Radiance arriving along wi (for a delta light: what stands in for it, so that the
  /// contribution is f |cos| li / pdf either way).
  Color li{0.f};
  /// Density of wi: solid angle, times the probability of having chosen this light; for a delta
  /// light the choice probability alone.
  float pdf = 0.f;
  bool delta = false;  ///< a point or directional light: no bounce ray can hit it (no MIS)
};

/// What a ray met among the light shapes that are not scene geometry (Whitted's sphere and
/// quad lights without an object of their own).
struct LightShapeHit {
  float t = 0.f;
  Color radiance{0.f};
  std::uint32_t light = 0;  ///< index in the sampler's list, for emitted_pdf
  Vec3 normal;              ///< the shape's normal at the hit
};

/// The lights of a scene, chosen by power.
///
/// Conventions (docs/rendering.md):
///  - emissive geometry emits `emission * emission_strength` on the side its normal points to
///    (a triangle's by its winding, a sphere's outward);
///  - a point light (a spot light within its cone) of intensity I gives irradiance pi I cos / d^2 (pi I cos when it
///  does not
///    fall off, as NFF lights do), a directional light pi I cos: a diffuse surface of albedo
///    rho then shows rho I cos, Whitted's value;
///  - a sphere or quad light that names no object of its own is an emitting shape of radiance
///    pi I / area (Whitted's brightness where it faces the point); one that names an object is
///    left to that object;
///  - the environment (or, without one, the settings' background) is a light too.
class LightSampler {
 public:
  /// The lights of `scene` (which must outlive the sampler).
  explicit LightSampler(const Scene& scene);

  /// True when the scene has no light at all.
  bool empty() const { return m_lights.empty(); }
  /// True when sample() reads its `u_choice` (more than one light to choose from).
  bool chooses() const { return m_lights.size() > 1; }

  /// Chooses a light with `u_choice`, a point on it with `u`, as seen from `p`; nullopt when
  /// the chosen light gives nothing there.
  std::optional<LightSample> sample(Vec3 p, float u_choice, Sample2 u) const;

  /// The density (as LightSample::pdf) with which sample() from `from` picks the point `at`
  /// (normal `normal`) of emissive scene primitive `prim`; 0 when that primitive is not a light.
  float emitter_pdf(Vec3 from, std::uint32_t prim, Vec3 at, Vec3 normal) const;

  /// The nearest of the light shapes that are not geometry along `ray` before `tmax`.
  std::optional<LightShapeHit> hit_light_shape(const Ray& ray, float tmax) const;
  /// As emitter_pdf, for a point of light shape `light` (from hit_light_shape).
  float light_shape_pdf(Vec3 from, std::uint32_t light, Vec3 at, Vec3 normal) const;

  /// Radiance of the environment along `dir` (every ray that leaves the scene sees it).
  Color environment(Vec3 dir) const;
  /// The density (as LightSample::pdf) with which sample() gives direction `dir` from the
  /// environment; 0 when the environment is black.
  float environment_pdf(Vec3 dir) const;

 private:
  enum class Kind : std::uint8_t {
    kPoint,
    kDirectional,
    kShape,
    kInstancedTriangle,
    kLightQuad,
    kLightSphere,
    kEnvironment
  };
  // An emissive triangle of an instanced prototype, carried into the world once.
  struct InstancedTriangle {
    Triangle world;           // the vertices in world space
    Vec3 normal;              // world outward normal (the instance's normal transform: mirrors keep it)
    std::uint32_t prototype;  // where its texture coordinates are
    std::uint32_t local;      // its id in the prototype
  };
  struct Entry {
    Kind kind;
    std::uint32_t index;                 // kPoint, kDirectional, kLight*: scene light; kShape: global primitive id
    float area = 0.f;                    // kShape, kLight*
    Color radiance{0.f};                 // kShape, kLight*: emitted radiance; kPoint, kDirectional: pi I
    const Material* textured = nullptr;  // kShape, kInstancedTriangle: the material, when it has an emission map
    std::uint32_t instanced = 0;         // kInstancedTriangle: index in m_instanced
  };

  // The solid-angle density of a point `at` (normal `normal`) of an area light of area `area`,
  // chosen with probability `choice`, seen from `from`.
  static float area_pdf(Vec3 from, Vec3 at, Vec3 normal, float area, float choice);

  const Scene& m_scene;
  std::vector<Entry> m_lights;
  // The probability of choosing entry `i`.
  float choice_probability(std::size_t i) const;

  std::optional<Distribution1D> m_choice;      // entries by power
  std::vector<std::int32_t> m_light_of_prim;   // entry of each flat primitive, -1 when not a light
  std::vector<InstancedTriangle> m_instanced;  // the instanced emitters' triangles
  std::unordered_map<std::uint32_t, std::int32_t> m_light_of_instanced;  // global id -> entry
  std::optional<EnvironmentLight> m_environment;
  std::int32_t m_environment_entry = -1;
  bool m_has_light_shapes = false;  // any kLightQuad or kLightSphere entry (hit_light_shape's loop)
};

}  // namespace raylab::detail
