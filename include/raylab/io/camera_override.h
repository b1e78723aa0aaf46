#pragma once
/// \file
/// The camera a caller sets over a scene's (the command line's --up, --camera-from, --camera-at,
/// --camera-up, --fov, --orbit): each given part replaces the scene's own, for every kind of
/// scene, and the result is checked as a scene file's camera is.

#include <optional>
#include <string>
#include <string_view>

#include "raylab/core/vec3.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// The camera parts a caller may set over a scene's; an empty member leaves the scene's.
struct CameraOverride {
  std::optional<Vec3> up_axis;         ///< --up: the axis a fitted camera stands on (one of kUpAxes)
  std::optional<Vec3> from;            ///< --camera-from: the eye
  std::optional<Vec3> at;              ///< --camera-at: the point looked at
  std::optional<Vec3> up;              ///< --camera-up: the up direction (any length but 0)
  std::optional<float> fov_degrees;    ///< --fov: the vertical field of view, as the scene's
  std::optional<float> orbit_degrees;  ///< --orbit: turn about the up direction through `at`

  /// True when no part is given.
  bool empty() const { return !up_axis && !from && !at && !up && !fov_degrees && !orbit_degrees; }
};

/// "X,Y,Z": three finite numbers separated by commas (spaces allowed around them); empty for
/// anything else.
std::optional<Vec3> parse_vec3(std::string_view text);

/// "X,Y,Z" that parse_vec3 reads back to the same floats, bit for bit.
std::string format_vec3(Vec3 v);

/// Why `degrees` cannot be a vertical field of view (it must lie in (0, 180)); empty when it can.
std::string fov_problem(float degrees);

/// Applies `over` to `scene`, in this order: `up_axis` places the fitted camera (and the fitted
/// lights) again for a mesh standing on that axis (fit_camera_and_lights); `from`, `at`, `up`
/// and `fov_degrees` replace the still camera's; `orbit_degrees` turns its eye about the up
/// direction through `at`, counter-clockwise seen from above. Throws UsageError naming the flag:
/// --up on a scene whose camera was not fitted, --fov outside (0, 180), an orbit that is not
/// finite, and a camera that cannot render (from == at, up parallel to the view). The camera
/// path of an animation is left as it is (the caller refuses the parts with --frames).
void apply_camera_override(Scene& scene, const CameraOverride& over);

/// The override as one line, for keys and messages ("up z, from 1,2,3, orbit 30"); empty when
/// nothing is given.
std::string describe_camera_override(const CameraOverride& over);

}  // namespace raylab
