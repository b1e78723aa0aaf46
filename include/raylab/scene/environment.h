#pragma once
/// \file
/// The light arriving from infinitely far away: a constant colour or a latitude-longitude
/// (equirectangular) image. Plain scene data; render/environment_light.h evaluates and samples
/// it, io/environment_io.h loads it.
///
/// Lat-long convention. +y is up (the scene's up axis). For a unit direction d = (x, y, z) in
/// the environment's own frame (the world frame turned back by rotate_degrees):
///
///     theta = acos(y)              in [0, pi]: 0 at the zenith (+y), pi at the nadir (-y)
///     phi   = atan2(z, x)          in [-pi, pi]: 0 at +x, pi/2 at +z, -pi/2 at -z
///     u     = 0.5 + phi / (2 pi)   in [0, 1]: 0 at the left edge of the image, 1 at the right
///     v     = theta / pi           in [0, 1]: 0 at the top row, 1 at the bottom row
///
/// and back: d = (sin(theta) cos(phi), cos(theta), sin(theta) sin(phi)) with
/// phi = 2 pi (u - 0.5), theta = pi v. So the centre of the image (u = 0.5, v = 0.5) lies on
/// the horizon along +x; u = 0.25 along -z, u = 0.75 along +z, and both side edges along -x.
/// Seen from inside, u grows to the right (the image is not mirrored).
///
/// This is Blender's mapping (Cycles' Environment Texture, equirectangular: image centre along
/// +X with Z up) carried over by the Z-up to Y-up conversion of Blender's glTF and OBJ
/// exporters (X stays X, Blender's Z becomes Y, Blender's Y becomes -Z): a scene exported from
/// Blender, lit by the same image, is lit the same way here with rotate_degrees = 0. A camera
/// looking along -z (Blender's front view) sees column u = 0.25 in the middle of its view; to
/// put the image's centre there instead, rotate by 90 degrees.
///
/// Texel (column i, row j) of a width x height image covers u in [i / width, (i + 1) / width)
/// and v in [j / height, (j + 1) / height), and the environment reads the texel that holds a
/// direction's (u, v) (nearest, no filtering; u = 1 reads the last column).

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "raylab/core/vec3.h"

namespace raylab {

/// A lat-long radiance image in linear RGB, as io/environment_io.h loads it.
struct EnvironmentImage {
  int width = 0;              ///< columns (u), > 0
  int height = 0;             ///< rows (v), > 0
  std::vector<Color> texels;  ///< width x height radiances, finite and >= 0, row-major; row 0 = top = zenith (+y)
  std::string path;           ///< the file it came from, for messages and reports (empty when made in memory)
};

/// The environment of a scene: what a ray that leaves the scene sees, and a light that
/// illuminates it from every direction.
struct Environment {
  /// Radiance from every direction when there is no image (linear RGB, >= 0); ignored with one.
  Color color{0.f};
  /// The lat-long image, or null for the constant `color`. Shared: the scene, its copies and
  /// the light built from it read one copy of what may be hundreds of megabytes.
  std::shared_ptr<const EnvironmentImage> image;
  /// Turns the environment about +y by the right-hand rule (counter-clockwise seen from above),
  /// in degrees: with 90, what lay along +x lies along -z.
  float rotate_degrees = 0.f;
  /// Multiplies the radiance of the colour or the image (>= 0).
  float scale = 1.f;

  /// True when the environment may send light: an image, or a colour that is not black, at a
  /// positive scale. False for the default, a scene that sets no environment.
  bool present() const { return scale > 0.f && (image != nullptr || max_component(color) > 0.f); }
};

/// The unit direction of lat-long image coordinates (u, v) in the environment's own frame, by
/// the convention above: the one rule for turning a texel into a direction, whoever draws or
/// reads an image.
inline Vec3 lat_long_direction(float u, float v) {
  const float phi = std::numbers::pi_v<float> * (2.f * u - 1.f);
  const float theta = std::numbers::pi_v<float> * v;
  const float sin_theta = std::sin(theta);
  return {sin_theta * std::cos(phi), std::cos(theta), sin_theta * std::sin(phi)};
}

}  // namespace raylab
