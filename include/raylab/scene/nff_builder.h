#pragma once
/// \file
/// Turns the entities of Eric Haines' Neutral File Format (NFF) into a Scene. The NFF reader and
/// the built-in SPD generators both speak through this one builder, so that `spd:NAME` and the
/// NFF file the original SPD program writes for NAME become the same Scene.

#include <cstdint>
#include <span>
#include <string>

#include "raylab/scene/mesh_builder.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// NFF's `v` entity.
struct NffView {
  Vec3 from{0.f, 0.f, 1.f};
  Vec3 at{0.f, 0.f, 0.f};
  Vec3 up{0.f, 1.f, 0.f};
  double angle = 45.0;  ///< degrees, from the centre of the first pixel row/column to the last
  double hither = 0.0;  ///< distance of the near plane from the eye
  int xres = 512;       ///< image width in pixels
  int yres = 512;       ///< image height in pixels
};

/// NFF's `f` entity: colour, diffuse and specular weights, Phong exponent, transmittance and
/// index of refraction. Ks weights both the highlight and the mirror-reflected ray; T is a
/// dielectric interface, split between reflection and refraction by Fresnel.
struct NffFill {
  Color color{1.f, 1.f, 1.f};
  float kd = 1.f;
  float ks = 0.f;
  float shine = 0.f;
  float transmittance = 0.f;
  float ior = 1.f;
};

/// Appends NFF entities to a Scene in the order they arrive. Each `fill` starts a new object
/// with its own material; primitives before the first `fill` use a white matte one.
class NffSceneBuilder {
 public:
  /// Builds into `scene`, which should be empty.
  explicit NffSceneBuilder(Scene& scene);

  /// `v`: camera and image size. The angle spans pixel centres (CameraSpec::FovSpan::kPixelCentres).
  void view(const NffView& view);
  /// `b`: background colour.
  void background(Color color);
  /// `l x y z`: a point light of unspecified intensity; see finish().
  void light(Vec3 position);
  /// `l x y z r g b`: a point light of the given colour.
  void light(Vec3 position, Color color);
  /// `f`: the material of the primitives that follow.
  void fill(const NffFill& fill);
  /// `s`: an analytic sphere.
  void sphere(Vec3 center, float radius);
  /// `c`: an open cone frustum (a cylinder when the radii are equal), kept analytic.
  void cone(Vec3 base, float base_radius, Vec3 apex, float apex_radius);
  /// `p`: a planar polygon, convex or not, triangulated by ear clipping.
  void polygon(std::span<const Vec3> vertices);
  /// `pp`: a polygon patch with a normal at every vertex, interpolated across each triangle.
  void patch(std::span<const Vec3> vertices, std::span<const Vec3> normals);

  /// Gives lights of unspecified intensity their value, 1 / sqrt(number of lights) each (NFF
  /// leaves it to the renderer; this keeps the total from blowing out with many lights), and
  /// returns what polygons were added and dropped. Call once, after the last entity.
  MeshLoadReport finish();

  /// Polygon counts so far.
  const MeshLoadReport& report() const { return m_report; }

 private:
  std::uint32_t current_object();

  Scene& m_scene;
  MeshLoadReport m_report;
  std::uint32_t m_object = kInvalidId;  ///< object of the current fill; created on first use
  NffFill m_fill;
  std::size_t m_fill_count = 0;
  std::vector<std::size_t> m_uncoloured_lights;  ///< indices into scene.lights
};

}  // namespace raylab
