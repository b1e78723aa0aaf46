// SPD 'gears' (Haines, SPD 3.14 gears.c): a size x size x size block of meshed gears, each a
// slab with 36 teeth, over a reflective floor, lit by five lights.
//
// Why it is built this way: each gear face is one 144-sided concave polygon (four corners per
// tooth: two on the tip circle, two on the root circle), so the scene tests a renderer's handling
// of large non-convex polygons; the 144 side walls are quadrilaterals. Neighbouring gears are
// turned half a tooth against each other so that their teeth mesh, and the tips stop 0.5% short
// of the gear's full radius so that meshing teeth never share a surface. Layers step down
// by 1/size; some gears are glassy, the rest matte, in colours from a cheap pseudo-random mix.
//
// Polygons: 1 floor + size^3 * (2 faces + 144 walls).

#include <algorithm>
#include <array>
#include <cmath>

#include "spd_generators.h"
#include "spd_lib.h"

namespace raylab::spd {
namespace {

using lib::DVec;

constexpr int kTeeth = 36;                // must be a multiple of 4
constexpr int kFaceCorners = 4 * kTeeth;  // corners of a gear face
constexpr double kTipRatio = 0.995;       // tip radius / full radius: the meshing clearance
constexpr double kRootRatio = 0.9;        // root radius / full radius
constexpr double kToothDepth = 1.0 - kRootRatio;
constexpr double kMaxThickness = 0.1;

using Face = std::array<DVec, kFaceCorners>;

// The corners of one gear face at height `z` relative to `center`, walking around the gear by
// `tooth_angle` per tooth (negative for the bottom face, so that each face winds counter-clockwise
// seen from outside the gear).
Face gear_face(DVec center, double offset_angle, double tooth_angle, double tip, double root, double z) {
  Face face;
  // Per tooth: the tip spans +-0.19 of the tooth angle, the root gap 0.3 to 0.7 of it.
  const std::array<double, 4> fraction{-0.19, 0.19, 0.3, 0.7};
  for (int tooth = 0; tooth < kTeeth; ++tooth) {
    const double angle =
        offset_angle + (tooth_angle > 0.0 ? 1.0 : -1.0) * 2.0 * lib::kPi * static_cast<double>(tooth) / kTeeth;
    for (int i = 0; i < 4; ++i) {
      const double radius = i < 2 ? tip : root;
      const double turn = angle + fraction[i] * tooth_angle;
      face[tooth * 4 + i] = center + DVec{radius * std::cos(turn), radius * std::sin(turn), z};
    }
  }
  return face;
}

// Emits one gear: top face, the side walls (down from each top edge), bottom face.
void gear(DVec center, double offset_angle, double tip, double root, double thickness, NffSceneBuilder& out) {
  const double tooth_angle = 2.0 * lib::kPi / kTeeth;
  const Face top = gear_face(center, offset_angle, tooth_angle, tip, root, 0.0);
  std::array<Vec3, kFaceCorners> polygon;
  for (int i = 0; i < kFaceCorners; ++i) polygon[i] = lib::to_float(top[i]);
  out.polygon(polygon);

  const DVec down{0.0, 0.0, thickness};
  for (int i = 0; i < kFaceCorners; ++i) {
    const DVec& here = top[i];
    const DVec& next = top[(i + 1) % kFaceCorners];
    const std::array<Vec3, 4> wall{lib::to_float(here), lib::to_float(here - down), lib::to_float(next - down),
                                   lib::to_float(next)};
    out.polygon(wall);
  }

  const Face bottom = gear_face(center, offset_angle, -tooth_angle, tip, root, -thickness);
  for (int i = 0; i < kFaceCorners; ++i) polygon[i] = lib::to_float(bottom[i]);
  out.polygon(polygon);
}

double fraction(double x) { return x - std::floor(x); }

// The gear's colour: a pseudo-random mix of its grid position, scaled so its largest channel is 1.
Color gear_color(int ix, int iy, int iz) {
  const double r = 0.01 + fraction(static_cast<double>(ix * 3 + iy * 2 + iz + 1) * 5.0 / 7.0);
  const double g = 0.01 + fraction(static_cast<double>(iy * 3 + iz * 2 + ix + 1) * 3.0 / 7.0);
  const double b = 0.01 + fraction(static_cast<double>(iz * 3 + ix * 2 + iy + 1) * 2.0 / 7.0);
  const double scale = std::max({r, g, b});
  return {static_cast<float>(r / scale), static_cast<float>(g / scale), static_cast<float>(b / scale)};
}

void generate(int size, NffSceneBuilder& out) {
  out.background(lib::kSkyBlue);
  out.view(lib::view({-1.1, -2.1, 2.6}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0));
  out.light({2.f, 4.f, 4.f});
  out.light({-2.f, 4.f, 3.f});
  out.light({2.f, -2.5f, 2.5f});
  out.light({-1.f, -4.f, 2.f});
  out.light({-1.111f, -2.121f, 2.626f});  // just behind the eye

  out.fill(lib::surface({1.f, 0.85f, 0.7f}, 0.3, 0.6, 37.0, 0.0, 0.0));
  const std::array<Vec3, 4> ground{Vec3{2.f, 2.f, 0.f}, Vec3{-2.f, 2.f, 0.f}, Vec3{-2.f, -2.f, 0.f},
                                   Vec3{2.f, -2.f, 0.f}};
  out.polygon(ground);

  // The full radius for which `size` gears in a row, each reaching a tooth depth into its
  // neighbour, span [-1, 1].
  const double n = size;
  const double radius = 1.0 / (n - (n - 1.0) * kToothDepth / 2.0);
  const double spacing = radius * (2.0 - kToothDepth);
  const double first = -1.0 + radius;
  const double thickness = std::min(kMaxThickness, 1.0 / (2.0 * n));
  for (int iz = 0; iz < size; ++iz) {
    for (int iy = 0; iy < size; ++iy) {
      for (int ix = 0; ix < size; ++ix) {
        const DVec center{first + ix * spacing, first + iy * spacing, 1.0 + iz * (-1.0 / n)};
        const Color color = gear_color(ix, iy, iz);
        if ((ix * 4 + iy * 2 + iz) % 5 == 0) {
          out.fill(lib::surface(color, 0.2, 0.0, 0.0, 0.8, 1.1));  // glassy
        } else {
          out.fill(lib::surface(color, 1.0, 0.0, 0.0, 0.0, 0.0));
        }
        // Neighbours alternate by half a tooth so that their teeth mesh.
        const double offset_angle = lib::kPi * static_cast<double>((ix + iy + iz) % 2) / kTeeth;
        gear(center, offset_angle, kTipRatio * radius, kRootRatio * radius, thickness, out);
      }
    }
  }
}

}  // namespace

SpdGenerator gears() {
  return {"gears", "size^3 meshed gears with concave 144-sided faces, over a mirror floor (size = gears per side)", 4,
          37, &generate};
}

}  // namespace raylab::spd
