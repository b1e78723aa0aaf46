#include "raylab/scene/camera_path.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

namespace raylab {
namespace {

using Field = Vec3 CameraSpec::*;

// Coordinates are interpolated in double and rounded once, so that a path whose keys move at a
// constant velocity gives the same floats whichever interpolation is chosen.
double coord(const CameraKey& key, Field field, int c) { return static_cast<double>((key.camera.*field)[c]); }

double frame_gap(const CameraKey& a, const CameraKey& b) {
  return static_cast<double>(b.frame) - static_cast<double>(a.frame);  // no int overflow
}

// Velocity per frame of coordinate `c` of `field` at key `k`: the derivative at key k of the
// parabola through keys k-1, k, k+1 (what the Barry-Goldman form of the Catmull-Rom spline
// gives with the frames as knots), i.e. the two neighbouring chord slopes weighted by the
// opposite gap. An end key has one neighbour: the chord slope to it.
double tangent(std::span<const CameraKey> keys, std::size_t k, Field field, int c) {
  auto slope = [&](std::size_t a, std::size_t b) {
    return (coord(keys[b], field, c) - coord(keys[a], field, c)) / frame_gap(keys[a], keys[b]);
  };
  if (k == 0) return slope(0, 1);
  if (k + 1 == keys.size()) return slope(k - 1, k);
  const double before = frame_gap(keys[k - 1], keys[k]);
  const double after = frame_gap(keys[k], keys[k + 1]);
  return (after * slope(k - 1, k) + before * slope(k, k + 1)) / (before + after);
}

// `field` between keys i and i + 1, at the fraction `t` of the interval.
Vec3 interpolate(std::span<const CameraKey> keys, std::size_t i, Field field, double t,
                 CameraPath::Interpolation interpolation) {
  const CameraKey& a = keys[i];
  const CameraKey& b = keys[i + 1];
  Vec3 out;
  for (int c = 0; c < 3; ++c) {
    const double p0 = coord(a, field, c);
    const double p1 = coord(b, field, c);
    if (interpolation == CameraPath::Interpolation::kLinear) {
      out[c] = static_cast<float>(p0 + (p1 - p0) * t);
      continue;
    }
    // Cubic Hermite basis; tangents are per frame, so they are scaled by the interval's length.
    const double gap = frame_gap(a, b);
    const double m0 = tangent(keys, i, field, c) * gap;
    const double m1 = tangent(keys, i + 1, field, c) * gap;
    const double t2 = t * t;
    const double t3 = t2 * t;
    out[c] = static_cast<float>((2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 +
                                (t3 - t2) * m1);
  }
  return out;
}

float lerp_number(float a, float b, double t) {
  const double da = a;
  return static_cast<float>(da + (static_cast<double>(b) - da) * t);
}

// The reasons a camera cannot be rendered; the same tests the scene reader applies to a camera.
std::optional<std::string> camera_problem(const CameraSpec& c) {
  if (!is_finite(c.from) || !is_finite(c.at) || !is_finite(c.up) || !std::isfinite(c.vfov_degrees) ||
      !std::isfinite(c.hither)) {
    return "has a value that is not finite";
  }
  const Vec3 forward = c.at - c.from;
  if (!(dot(forward, forward) > 0.f)) return "has 'from' and 'at' at the same point";
  const Vec3 side = cross(forward, c.up);
  if (!(dot(side, side) > 0.f)) return "has 'up' parallel to the viewing direction (or zero)";
  return std::nullopt;
}

}  // namespace

CameraSpec CameraPath::at_time(double frame) const {
  if (keys.empty()) return CameraSpec{};
  // Clamped at both ends; `!(frame > first)` also sends a NaN frame to the first key.
  if (!(frame > keys.front().frame)) return keys.front().camera;
  if (frame >= keys.back().frame) return keys.back().camera;
  // The interval [keys[i].frame, keys[i + 1].frame) that holds `frame`.
  const auto next =
      std::upper_bound(keys.begin(), keys.end(), frame, [](double f, const CameraKey& k) { return f < k.frame; });
  const auto i = static_cast<std::size_t>(next - keys.begin()) - 1;
  const CameraKey& a = keys[i];
  if (frame == a.frame) return a.camera;  // exact at a key, whatever rounding would do
  const CameraKey& b = keys[i + 1];
  const double t = (frame - a.frame) / frame_gap(a, b);
  CameraSpec out = a.camera;  // fov_span from the earlier key
  out.from = interpolate(keys, i, &CameraSpec::from, t, interpolation);
  out.at = interpolate(keys, i, &CameraSpec::at, t, interpolation);
  out.up = interpolate(keys, i, &CameraSpec::up, t, interpolation);
  out.vfov_degrees = lerp_number(a.camera.vfov_degrees, b.camera.vfov_degrees, t);
  out.hither = lerp_number(a.camera.hither, b.camera.hither, t);
  return out;
}

std::optional<std::string> CameraPath::check() const {
  for (std::size_t i = 1; i < keys.size(); ++i) {
    if (keys[i].frame <= keys[i - 1].frame) {
      return "key " + std::to_string(i) + " (frame " + std::to_string(keys[i].frame) + ") does not come after key " +
             std::to_string(i - 1) + " (frame " + std::to_string(keys[i - 1].frame) +
             "): frames must strictly increase";
    }
  }
  if (keys.empty()) return std::nullopt;
  // 64-bit counter: the last frame may be INT_MAX.
  for (std::int64_t f = first_frame(); f <= last_frame(); ++f) {
    if (const auto problem = camera_problem(at(static_cast<int>(f)))) {
      return "the camera at frame " + std::to_string(f) + " " + *problem;
    }
  }
  return std::nullopt;
}

}  // namespace raylab
