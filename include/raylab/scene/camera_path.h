#pragma once
/// \file
/// An animated camera: cameras at key frames and the interpolation between them, so that one
/// scene describes a sequence of images (frame 0, 1, 2, ...). Plain data, like the rest of the
/// scene; which frames to render is the caller's choice.

#include <optional>
#include <string>
#include <vector>

#include "raylab/scene/camera_spec.h"

namespace raylab {

/// The camera at one key frame.
struct CameraKey {
  /// The frame number at which the camera is exactly `camera`.
  int frame = 0;
  /// The camera at that frame.
  CameraSpec camera;
};

/// A camera that moves: keys in strictly increasing frame order, interpolated in between and
/// held constant before the first key and after the last. Empty for a still.
struct CameraPath {
  /// How `from`, `at` and `up` move between keys (`vfov_degrees` and `hither` are always linear).
  enum class Interpolation {
    /// Straight lines between keys, at constant speed within each interval: `lerp`.
    kLinear,
    /// A C1 curve through every key: the Catmull-Rom spline with the key frames as its knots
    /// (the non-uniform form of Barry and Goldman), so that unevenly spaced keys keep a smooth
    /// speed. Each interval is a cubic Hermite segment whose tangent at a key is the derivative
    /// of the parabola through that key and its two neighbours; at the first and last key,
    /// which have one neighbour, it is the slope of the chord to it (the end key duplicated).
    /// Keys moving at a constant velocity (positions linear in the frame number) give exactly
    /// the linear path; two keys give the linear path.
    kSmooth,
  };

  /// The interpolation between keys.
  Interpolation interpolation = Interpolation::kLinear;
  /// The keys, in strictly increasing frame order (check() says when they are not).
  std::vector<CameraKey> keys;

  /// True for a still: no keys.
  bool empty() const { return keys.empty(); }
  /// The frame of the first key. Requires !empty().
  int first_frame() const { return keys.front().frame; }
  /// The frame of the last key. Requires !empty().
  int last_frame() const { return keys.back().frame; }

  /// The camera at `frame`: exactly a key's camera (bit for bit) at its frame; the first key's
  /// before it and the last key's after it; in between, `from`, `at` and `up` interpolated as
  /// `interpolation` says, `vfov_degrees` and `hither` linearly, `fov_span` and `framed_aspect`
  /// taken from the earlier key. Requires keys in increasing frame order; an empty path gives `CameraSpec{}`.
  CameraSpec at(int frame) const { return at_time(static_cast<double>(frame)); }
  /// The camera at a fractional frame (a time inside a frame, for motion blur or sub-frames),
  /// by the same rules; at_time(f) == at(f) for every integer f.
  CameraSpec at_time(double frame) const;

  /// Why the path cannot be rendered, or nullopt when it can: frames not strictly increasing,
  /// or a frame from first_frame() to last_frame() whose camera has a non-finite value, `from`
  /// equal to `at`, or `up` parallel to the viewing direction (which interpolation can produce
  /// between valid keys: an `up` turning through zero, an eye passing through the point it
  /// looks at). The message names the first such frame. Costs one at() per frame in the range.
  std::optional<std::string> check() const;
};

}  // namespace raylab
