// SPD 'mount' (Haines, SPD 3.14 mount.c): a fractal mountain over [-1, 1]^2 with a pyramid of
// four glass spheres in front of it, lit by one distant light.
//
// Why it is built this way: the mountain is Carpenter's midpoint displacement carried over to a
// square grid. A square with known corner heights is split into four; each edge midpoint takes
// the mean of its edge's two corners and the centre the mean of all four, each plus a Gaussian
// offset whose spread shrinks with the square's size (by a factor set by the fractal dimension
// 2.2), so that the surface looks equally rough at every scale. At level `size` the grid has
// 2^size cells a side, each split into two triangles: 2 * 4^size triangles.
//
// The offsets are not drawn from a running random stream but from a seed hashed from the
// midpoint's grid coordinates, so that the two squares sharing an edge agree on its midpoint and
// the surface has no cracks. SPD's hash (kept here because it defines the reference mountain)
// is known to be poor: it repeats, so parts of the mountain recur. The seed feeds the small
// linear congruential generator of SPD's lib_gauss_rand and Marsaglia's polar method, exactly as
// there, so that the mountain matches the original's triangle for triangle.

#include <array>
#include <cmath>
#include <cstdint>

#include "spd_generators.h"
#include "spd_lib.h"

namespace raylab::spd {
namespace {

using lib::DVec;
using lib::Rotation;

constexpr double kFractalDimension = 2.2;  // between 2 (smooth) and 3 (space-filling)
constexpr long kMountainNumber = 21;       // added to every seed; another number, another mountain
constexpr double kCorner = -1.0;           // the mountain covers [kCorner, kCorner + kWidth]^2
constexpr double kWidth = 2.0;

// SPD's seed hash of grid point (x, y) at subdivision level `level`: shifted copies of the
// coordinates, summed, kept to 16 bits. Shift counts that would be negative (level > 7 for the
// third term) are undefined in C; compiled on x86 the count wraps to 60 or more, which moves
// every bit out of the 16 kept, so such a term contributes nothing, as here.
long seed_hash(int x, int y, int level) {
  const auto term = [](int value, int shift) -> std::uint64_t {
    return shift < 0 ? 0 : static_cast<std::uint64_t>(static_cast<unsigned>(value)) << shift;
  };
  return static_cast<long>((term(x, 23 - level) + term(y, 15 - level) + term(x, 7 - level)) & 0xffffu);
}

// A standard normal deviate from `seed` (SPD's lib_gauss_rand): pairs from the linear
// congruential generator x' = (28411 + 8121 x) mod 134456, mapped to [-1, 1)^2, until one falls
// inside the unit circle, then Marsaglia's polar transform of it.
double gauss(long seed) {
  constexpr long kModulus = 134456, kMultiplier = 8121, kIncrement = 28411;
  long second = seed;
  double u = 0.0, v = 0.0, r = 0.0;
  do {
    const long first = (kIncrement + second * kMultiplier) % kModulus;
    second = (kIncrement + first * kMultiplier) % kModulus;
    u = first * 2.0 / kModulus - 1.0;
    v = second * 2.0 / kModulus - 1.0;
    r = u * u + v * v;
  } while (r >= 1.0);
  return u * std::sqrt(-2.0 * std::log(r) / r);
}

// Heights at the corners of a grid square: lower left, lower right, upper right, upper left.
struct Corners {
  double ll, lr, ur, ul;
};

class Mountain {
 public:
  Mountain(int level, NffSceneBuilder& out) : m_level(level), m_cells(1 << level), m_out(out) {
    // Each halving of the square scales the offsets by sqrt(ratio^2 - 1) relative to its side.
    const double ratio = 2.0 / std::exp(std::log(2.0) / (kFractalDimension - 1.0));
    m_roughness = std::sqrt(ratio * ratio - 1.0);
  }

  // Emits the square of `width` cells with lower left cell (x, y) and corner heights `z`.
  void grow(int width, int x, int y, Corners z) {
    if (width == 1) {
      emit_cell(x, y, z);
      return;
    }
    const int half = width >> 1;
    const double rise = half * kWidth / m_cells * m_roughness;
    const double lower = (z.ll + z.lr) / 2.0 + rise * offset(x + half, y);
    const double right = (z.lr + z.ur) / 2.0 + rise * offset(x + width, y + half);
    const double upper = (z.ur + z.ul) / 2.0 + rise * offset(x + half, y + width);
    const double left = (z.ul + z.ll) / 2.0 + rise * offset(x, y + half);
    // The centre is a diagonal's midpoint, sqrt(2) times as far from its ends.
    const double middle = (z.ll + z.lr + z.ur + z.ul) / 4.0 + 1.4142136 * rise * offset(x + half, y + half);
    grow(half, x, y, {z.ll, lower, middle, left});
    grow(half, x + half, y, {lower, z.lr, right, middle});
    grow(half, x + half, y + half, {middle, right, z.ur, upper});
    grow(half, x, y + half, {left, middle, upper, z.ul});
  }

 private:
  double offset(int x, int y) const { return gauss(kMountainNumber + seed_hash(x, y, m_level)); }

  double grid(int i) const { return kCorner + i * kWidth / m_cells; }

  // One grid cell as two triangles, split along its lower-left to upper-right diagonal.
  void emit_cell(int x, int y, const Corners& z) {
    const Vec3 ll = lib::to_float({grid(x), grid(y), z.ll});
    const Vec3 lr = lib::to_float({grid(x + 1), grid(y), z.lr});
    const Vec3 ur = lib::to_float({grid(x + 1), grid(y + 1), z.ur});
    const Vec3 ul = lib::to_float({grid(x), grid(y + 1), z.ul});
    m_out.polygon(std::array<Vec3, 3>{ll, lr, ur});
    m_out.polygon(std::array<Vec3, 3>{ur, ul, ll});
  }

  int m_level;
  int m_cells;  // grid cells along a side
  double m_roughness = 0.0;
  NffSceneBuilder& m_out;
};

// Four touching spheres of radius `radius` at the corners of a regular tetrahedron centred on
// `centre`, one corner straight up: a tetrahedron of edge 2r has circumradius r * sqrt(3/2), and
// its corners are acos(-1/3) apart as seen from the centre.
void sphere_pyramid(DVec centre, double radius, NffSceneBuilder& out) {
  const DVec apex{0.0, 0.0, radius * std::sqrt(3.0 / 2.0)};
  out.sphere(lib::to_float(centre + apex), static_cast<float>(radius));
  const DVec foot = Rotation(lib::normalized(DVec{1.0, 1.0, 0.0}), std::acos(-1.0 / 3.0))(apex);
  for (int i = 0; i < 3; ++i) {
    out.sphere(lib::to_float(Rotation::about_z(i * 2.0 * lib::kPi / 3.0)(foot) + centre), static_cast<float>(radius));
  }
}

void generate(int size, NffSceneBuilder& out) {
  out.background(lib::kSkyBlue);
  out.view(lib::view({-1.6, 1.6, 1.7}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0.01));
  out.light({-100.f, -100.f, 100.f});

  out.fill(lib::surface({1.f, 1.f, 1.f}, 0.1, 0.1, 6.7, 0.9, 1.5));  // clear glass
  sphere_pyramid({-0.8, 0.8, 1.0}, 0.17, out);

  out.fill(lib::surface({0.5f, 0.45f, 0.35f}, 1.0, 0.0, 0.0, 0.0, 0.0));
  Mountain mountain(size, out);
  mountain.grow(1 << size, 0, 0, {0.0, 0.0, 0.0, 0.0});
}

}  // namespace

SpdGenerator mount() {
  return {"mount", "fractal mountain of 2*4^size triangles with 4 glass spheres (size = subdivision level)", 6, 11,
          &generate};
}

}  // namespace raylab::spd
