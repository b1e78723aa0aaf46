// SPD 'tetra' (Haines, SPD 3.14 tetra.c): a recursive tetrahedral pyramid, the scene Glassner
// (1984) and Kay & Kajiya (1986) timed their ray tracers on, red, lit by one light.
//
// Why it is built this way: a regular tetrahedron is four alternate corners of a cube, and
// the four half-size cubes in those same corners hold tetrahedra that touch at their corners
// and leave the middle octahedron empty. Recursing `size` levels (level 1 is a single
// tetrahedron) gives the Sierpinski pyramid: 4^size triangles, most of space empty, many
// shadow rays grazing edges, which is what made it a hard test for space subdivision.
// The camera and light are Kay's, moved into SPD's world coordinates.

#include <array>

#include "spd_generators.h"
#include "spd_lib.h"

namespace raylab::spd {
namespace {

using lib::DVec;

// The cube corners (x, y, z in {-1, 1}) with x*y*z = 1, i.e. one of the cube's two inscribed
// tetrahedra, in SPD's order (x slowest, z fastest).
constexpr std::array<std::array<int, 3>, 4> kCorners{{{-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}, {1, 1, 1}}};

// Corner indices of the four faces, each wound as SPD winds it.
constexpr std::array<std::array<int, 3>, 4> kFaces{{{0, 1, 2}, {3, 2, 1}, {2, 3, 0}, {1, 0, 3}}};

DVec corner(DVec center, double half, int i) {
  return center + DVec{kCorners[i][0] * half, kCorners[i][1] * half, kCorners[i][2] * half};
}

// Emits the tetrahedron inscribed in the cube of half-width `half` about `center`, or, above
// level 1, the four half-size pyramids in its corners.
void pyramid(int level, DVec center, double half, NffSceneBuilder& out) {
  if (level <= 1) {
    for (const auto& face : kFaces) {
      const std::array<Vec3, 3> triangle{lib::to_float(corner(center, half, face[0])),
                                         lib::to_float(corner(center, half, face[1])),
                                         lib::to_float(corner(center, half, face[2]))};
      out.polygon(triangle);
    }
    return;
  }
  for (int i = 0; i < 4; ++i) pyramid(level - 1, corner(center, half / 2.0, i), half / 2.0, out);
}

void generate(int size, NffSceneBuilder& out) {
  out.background(lib::kSkyBlue);
  out.view(lib::view({1.022846, -3.177154, -2.174512}, {-0.004103, -0.004103, 0.216539},
                     {-0.816497, -0.816497, 0.816497}, 1.0));
  out.light({2.f, -18.f, -5.f});
  out.fill(lib::surface({1.f, 0.2f, 0.2f}, 1.0, 0.0, 0.0, 0.0, 0.0));
  pyramid(size, {0.0, 0.0, 0.0}, 1.0, out);
}

}  // namespace

SpdGenerator tetra() {
  return {"tetra", "recursive tetrahedral (Sierpinski) pyramid of 4^size triangles (size = depth)", 6, 12, &generate};
}

}  // namespace raylab::spd
