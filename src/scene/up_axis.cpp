#include "raylab/scene/up_axis.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace raylab {
namespace {

// A face within 5 degrees of an axis counts as facing along it: a scan cut by a plane is flat
// only to the scanner's noise (nefertiti.obj: a sixth of its base is tilted by 3 to 5 degrees).
constexpr float kFacingCos = 0.9962f;
// How close to the end of the bounds, as a fraction of the extent, a base face must lie.
constexpr float kEndTolerance = 0.01f;

}  // namespace

std::array<float, 6> flat_base_fractions(const Scene& scene) {
  std::array<float, 6> fractions{};
  const Box3 box = scene.geometry.bounds();
  if (box.empty()) return fractions;
  const Vec3 extent = box.extent();
  // Areas in double: a mesh of a million small faces adds without losing the small ones.
  std::array<double, 6> area{};
  for (const Triangle& t : scene.geometry.triangles) {
    const Vec3 n = cross(t.p1 - t.p0, t.p2 - t.p0);
    const float twice_area = length(n);
    if (!(twice_area > 0.f)) continue;
    const Vec3 centroid = (t.p0 + t.p1 + t.p2) / 3.f;
    for (int axis = 0; axis < 3; ++axis) {
      if (std::fabs(n[axis]) < kFacingCos * twice_area) continue;
      const float tolerance = kEndTolerance * extent[axis];
      // kUpAxes: +Y, +Z, +X, -Y, -Z, -X; a base at the low end is below the positive axis.
      const int positive = axis == 1 ? 0 : axis == 2 ? 1 : 2;
      if (centroid[axis] - box.lo[axis] <= tolerance) area[positive] += 0.5 * twice_area;
      if (box.hi[axis] - centroid[axis] <= tolerance) area[positive + 3] += 0.5 * twice_area;
    }
  }
  for (int i = 0; i < 6; ++i) {
    const Vec3 axis = abs(kUpAxes[i]);
    const double section =
        static_cast<double>(dot(Vec3{extent.y * extent.z, extent.z * extent.x, extent.x * extent.y}, axis));
    fractions[i] = section > 0.0 ? static_cast<float>(area[i] / section) : 0.f;
  }
  return fractions;
}

std::optional<Vec3> detect_up_axis(const Scene& scene) {
  const std::array<float, 6> fractions = flat_base_fractions(scene);
  const float best = *std::max_element(fractions.begin(), fractions.end());
  if (best < kMinBaseFraction) return std::nullopt;
  for (int i = 0; i < 6; ++i) {
    if (fractions[i] >= 0.9f * best) return kUpAxes[i];
  }
  return std::nullopt;
}

std::optional<Vec3> parse_up_axis(std::string_view name) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.starts_with('+')) lower.erase(0, 1);
  for (const Vec3 axis : kUpAxes) {
    if (lower == up_axis_name(axis)) return axis;
  }
  return std::nullopt;
}

std::string up_axis_name(Vec3 axis) {
  const char* letter = axis.x != 0.f ? "x" : axis.y != 0.f ? "y" : "z";
  return (axis.x + axis.y + axis.z < 0.f ? "-" : "") + std::string(letter);
}

}  // namespace raylab
