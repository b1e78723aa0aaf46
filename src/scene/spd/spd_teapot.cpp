// SPD 'teapot' (Eric Haines, SPD 3.14): the Utah teapot's 32 bicubic Bezier patches (Newell's 28
// plus Crow's four-patch bottom) tessellated into smooth-shaded triangles, sitting on a checkered
// square that is meshed to the same degree, lit by two lights.
//
// Size factor n cuts each patch into an n x n grid of quadrilaterals in (s, t), each split into two
// triangles with the exact surface normal at every corner. The lid's knob and the bottom close at
// a point on the z axis (a whole row of control points is one point there): a triangle with two
// corners on that pole has no area and is not written; one with a single corner there gets the
// axis as its normal at the pole, where the surface derivative vanishes and gives none. That
// makes 64n^2 - 8n teapot triangles plus n^2 checker squares. At n = 1 four of the 56 (the spout
// tip, whose corner control points are collinear) have no area either; the original writes them
// and so does this generator, and the scene builder drops them, as it would reading the file.

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "spd_generators.h"
#include "spd_lib.h"

namespace raylab::spd {
namespace {

struct P3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

P3 operator+(P3 a, P3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
P3 operator*(double s, P3 a) { return {s * a.x, s * a.y, s * a.z}; }
P3 cross(P3 a, P3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

/// Unit-length `a`, or `a` itself when it has no length (as the SPD library's normalisation).
P3 normalized(P3 a) {
  const double len = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
  return len > 0.0 ? (1.0 / len) * a : a;
}

Vec3 to_vec3(P3 p) { return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)}; }

// The teapot's control points, as the SPD program numbers them (data, public since Newell 1975).
// clang-format off
constexpr P3 kControlPoints[290] = {
    {1.4, 0, 2.4}, {1.4, -0.784, 2.4}, {0.784, -1.4, 2.4}, {0, -1.4, 2.4},  // 0
    {1.3375, 0, 2.53125}, {1.3375, -0.749, 2.53125}, {0.749, -1.3375, 2.53125}, {0, -1.3375, 2.53125},  // 4
    {1.4375, 0, 2.53125}, {1.4375, -0.805, 2.53125}, {0.805, -1.4375, 2.53125}, {0, -1.4375, 2.53125},  // 8
    {1.5, 0, 2.4}, {1.5, -0.84, 2.4}, {0.84, -1.5, 2.4}, {0, -1.5, 2.4},  // 12
    {-0.784, -1.4, 2.4}, {-1.4, -0.784, 2.4}, {-1.4, 0, 2.4}, {-0.749, -1.3375, 2.53125},  // 16
    {-1.3375, -0.749, 2.53125}, {-1.3375, 0, 2.53125}, {-0.805, -1.4375, 2.53125}, {-1.4375, -0.805, 2.53125},  // 20
    {-1.4375, 0, 2.53125}, {-0.84, -1.5, 2.4}, {-1.5, -0.84, 2.4}, {-1.5, 0, 2.4},  // 24
    {-1.4, 0.784, 2.4}, {-0.784, 1.4, 2.4}, {0, 1.4, 2.4}, {-1.3375, 0.749, 2.53125},  // 28
    {-0.749, 1.3375, 2.53125}, {0, 1.3375, 2.53125}, {-1.4375, 0.805, 2.53125}, {-0.805, 1.4375, 2.53125},  // 32
    {0, 1.4375, 2.53125}, {-1.5, 0.84, 2.4}, {-0.84, 1.5, 2.4}, {0, 1.5, 2.4},  // 36
    {0.784, 1.4, 2.4}, {1.4, 0.784, 2.4}, {0.749, 1.3375, 2.53125}, {1.3375, 0.749, 2.53125},  // 40
    {0.805, 1.4375, 2.53125}, {1.4375, 0.805, 2.53125}, {0.84, 1.5, 2.4}, {1.5, 0.84, 2.4},  // 44
    {1.75, 0, 1.875}, {1.75, -0.98, 1.875}, {0.98, -1.75, 1.875}, {0, -1.75, 1.875},  // 48
    {2, 0, 1.35}, {2, -1.12, 1.35}, {1.12, -2, 1.35}, {0, -2, 1.35},  // 52
    {2, 0, 0.9}, {2, -1.12, 0.9}, {1.12, -2, 0.9}, {0, -2, 0.9},  // 56
    {-0.98, -1.75, 1.875}, {-1.75, -0.98, 1.875}, {-1.75, 0, 1.875}, {-1.12, -2, 1.35},  // 60
    {-2, -1.12, 1.35}, {-2, 0, 1.35}, {-1.12, -2, 0.9}, {-2, -1.12, 0.9},  // 64
    {-2, 0, 0.9}, {-1.75, 0.98, 1.875}, {-0.98, 1.75, 1.875}, {0, 1.75, 1.875},  // 68
    {-2, 1.12, 1.35}, {-1.12, 2, 1.35}, {0, 2, 1.35}, {-2, 1.12, 0.9},  // 72
    {-1.12, 2, 0.9}, {0, 2, 0.9}, {0.98, 1.75, 1.875}, {1.75, 0.98, 1.875},  // 76
    {1.12, 2, 1.35}, {2, 1.12, 1.35}, {1.12, 2, 0.9}, {2, 1.12, 0.9},  // 80
    {2, 0, 0.45}, {2, -1.12, 0.45}, {1.12, -2, 0.45}, {0, -2, 0.45},  // 84
    {1.5, 0, 0.225}, {1.5, -0.84, 0.225}, {0.84, -1.5, 0.225}, {0, -1.5, 0.225},  // 88
    {1.5, 0, 0.15}, {1.5, -0.84, 0.15}, {0.84, -1.5, 0.15}, {0, -1.5, 0.15},  // 92
    {-1.12, -2, 0.45}, {-2, -1.12, 0.45}, {-2, 0, 0.45}, {-0.84, -1.5, 0.225},  // 96
    {-1.5, -0.84, 0.225}, {-1.5, 0, 0.225}, {-0.84, -1.5, 0.15}, {-1.5, -0.84, 0.15},  // 100
    {-1.5, 0, 0.15}, {-2, 1.12, 0.45}, {-1.12, 2, 0.45}, {0, 2, 0.45},  // 104
    {-1.5, 0.84, 0.225}, {-0.84, 1.5, 0.225}, {0, 1.5, 0.225}, {-1.5, 0.84, 0.15},  // 108
    {-0.84, 1.5, 0.15}, {0, 1.5, 0.15}, {1.12, 2, 0.45}, {2, 1.12, 0.45},  // 112
    {0.84, 1.5, 0.225}, {1.5, 0.84, 0.225}, {0.84, 1.5, 0.15}, {1.5, 0.84, 0.15},  // 116
    {-1.6, 0, 2.025}, {-1.6, -0.3, 2.025}, {-1.5, -0.3, 2.25}, {-1.5, 0, 2.25},  // 120
    {-2.3, 0, 2.025}, {-2.3, -0.3, 2.025}, {-2.5, -0.3, 2.25}, {-2.5, 0, 2.25},  // 124
    {-2.7, 0, 2.025}, {-2.7, -0.3, 2.025}, {-3, -0.3, 2.25}, {-3, 0, 2.25},  // 128
    {-2.7, 0, 1.8}, {-2.7, -0.3, 1.8}, {-3, -0.3, 1.8}, {-3, 0, 1.8},  // 132
    {-1.5, 0.3, 2.25}, {-1.6, 0.3, 2.025}, {-2.5, 0.3, 2.25}, {-2.3, 0.3, 2.025},  // 136
    {-3, 0.3, 2.25}, {-2.7, 0.3, 2.025}, {-3, 0.3, 1.8}, {-2.7, 0.3, 1.8},  // 140
    {-2.7, 0, 1.575}, {-2.7, -0.3, 1.575}, {-3, -0.3, 1.35}, {-3, 0, 1.35},  // 144
    {-2.5, 0, 1.125}, {-2.5, -0.3, 1.125}, {-2.65, -0.3, 0.9375}, {-2.65, 0, 0.9375},  // 148
    {-2, -0.3, 0.9}, {-1.9, -0.3, 0.6}, {-1.9, 0, 0.6}, {-3, 0.3, 1.35},  // 152
    {-2.7, 0.3, 1.575}, {-2.65, 0.3, 0.9375}, {-2.5, 0.3, 1.125}, {-1.9, 0.3, 0.6},  // 156
    {-2, 0.3, 0.9}, {1.7, 0, 1.425}, {1.7, -0.66, 1.425}, {1.7, -0.66, 0.6},  // 160
    {1.7, 0, 0.6}, {2.6, 0, 1.425}, {2.6, -0.66, 1.425}, {3.1, -0.66, 0.825},  // 164
    {3.1, 0, 0.825}, {2.3, 0, 2.1}, {2.3, -0.25, 2.1}, {2.4, -0.25, 2.025},  // 168
    {2.4, 0, 2.025}, {2.7, 0, 2.4}, {2.7, -0.25, 2.4}, {3.3, -0.25, 2.4},  // 172
    {3.3, 0, 2.4}, {1.7, 0.66, 0.6}, {1.7, 0.66, 1.425}, {3.1, 0.66, 0.825},  // 176
    {2.6, 0.66, 1.425}, {2.4, 0.25, 2.025}, {2.3, 0.25, 2.1}, {3.3, 0.25, 2.4},  // 180
    {2.7, 0.25, 2.4}, {2.8, 0, 2.475}, {2.8, -0.25, 2.475}, {3.525, -0.25, 2.49375},  // 184
    {3.525, 0, 2.49375}, {2.9, 0, 2.475}, {2.9, -0.15, 2.475}, {3.45, -0.15, 2.5125},  // 188
    {3.45, 0, 2.5125}, {2.8, 0, 2.4}, {2.8, -0.15, 2.4}, {3.2, -0.15, 2.4},  // 192
    {3.2, 0, 2.4}, {3.525, 0.25, 2.49375}, {2.8, 0.25, 2.475}, {3.45, 0.15, 2.5125},  // 196
    {2.9, 0.15, 2.475}, {3.2, 0.15, 2.4}, {2.8, 0.15, 2.4}, {0, 0, 3.15},  // 200
    {0.8, 0, 3.15}, {0.8, -0.45, 3.15}, {0.45, -0.8, 3.15}, {0, -0.8, 3.15},  // 204
    {0, 0, 2.85}, {0.2, 0, 2.7}, {0.2, -0.112, 2.7}, {0.112, -0.2, 2.7},  // 208
    {0, -0.2, 2.7}, {-0.45, -0.8, 3.15}, {-0.8, -0.45, 3.15}, {-0.8, 0, 3.15},  // 212
    {-0.112, -0.2, 2.7}, {-0.2, -0.112, 2.7}, {-0.2, 0, 2.7}, {-0.8, 0.45, 3.15},  // 216
    {-0.45, 0.8, 3.15}, {0, 0.8, 3.15}, {-0.2, 0.112, 2.7}, {-0.112, 0.2, 2.7},  // 220
    {0, 0.2, 2.7}, {0.45, 0.8, 3.15}, {0.8, 0.45, 3.15}, {0.112, 0.2, 2.7},  // 224
    {0.2, 0.112, 2.7}, {0.4, 0, 2.55}, {0.4, -0.224, 2.55}, {0.224, -0.4, 2.55},  // 228
    {0, -0.4, 2.55}, {1.3, 0, 2.55}, {1.3, -0.728, 2.55}, {0.728, -1.3, 2.55},  // 232
    {0, -1.3, 2.55}, {1.3, 0, 2.4}, {1.3, -0.728, 2.4}, {0.728, -1.3, 2.4},  // 236
    {0, -1.3, 2.4}, {-0.224, -0.4, 2.55}, {-0.4, -0.224, 2.55}, {-0.4, 0, 2.55},  // 240
    {-0.728, -1.3, 2.55}, {-1.3, -0.728, 2.55}, {-1.3, 0, 2.55}, {-0.728, -1.3, 2.4},  // 244
    {-1.3, -0.728, 2.4}, {-1.3, 0, 2.4}, {-0.4, 0.224, 2.55}, {-0.224, 0.4, 2.55},  // 248
    {0, 0.4, 2.55}, {-1.3, 0.728, 2.55}, {-0.728, 1.3, 2.55}, {0, 1.3, 2.55},  // 252
    {-1.3, 0.728, 2.4}, {-0.728, 1.3, 2.4}, {0, 1.3, 2.4}, {0.224, 0.4, 2.55},  // 256
    {0.4, 0.224, 2.55}, {0.728, 1.3, 2.55}, {1.3, 0.728, 2.55}, {0.728, 1.3, 2.4},  // 260
    {1.3, 0.728, 2.4}, {0, 0, 0}, {1.425, 0, 0}, {1.425, 0.798, 0},  // 264
    {0.798, 1.425, 0}, {0, 1.425, 0}, {1.5, 0, 0.075}, {1.5, 0.84, 0.075},  // 268
    {0.84, 1.5, 0.075}, {0, 1.5, 0.075}, {-0.798, 1.425, 0}, {-1.425, 0.798, 0},  // 272
    {-1.425, 0, 0}, {-0.84, 1.5, 0.075}, {-1.5, 0.84, 0.075}, {-1.5, 0, 0.075},  // 276
    {-1.425, -0.798, 0}, {-0.798, -1.425, 0}, {0, -1.425, 0}, {-1.5, -0.84, 0.075},  // 280
    {-0.84, -1.5, 0.075}, {0, -1.5, 0.075}, {0.798, -1.425, 0}, {1.425, -0.798, 0},  // 284
    {0.84, -1.5, 0.075}, {1.5, -0.84, 0.075},  // 288
};
// clang-format on

// Each patch's 4 x 4 control points, row by row: the row is the patch's s direction, the column
// its t direction. Rim, body, handle, spout, lid, bottom; each part's patches go round the z axis.
constexpr int kPatches[32][16] = {
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
    {3, 16, 17, 18, 7, 19, 20, 21, 11, 22, 23, 24, 15, 25, 26, 27},
    {18, 28, 29, 30, 21, 31, 32, 33, 24, 34, 35, 36, 27, 37, 38, 39},
    {30, 40, 41, 0, 33, 42, 43, 4, 36, 44, 45, 8, 39, 46, 47, 12},
    {12, 13, 14, 15, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59},
    {15, 25, 26, 27, 51, 60, 61, 62, 55, 63, 64, 65, 59, 66, 67, 68},
    {27, 37, 38, 39, 62, 69, 70, 71, 65, 72, 73, 74, 68, 75, 76, 77},
    {39, 46, 47, 12, 71, 78, 79, 48, 74, 80, 81, 52, 77, 82, 83, 56},
    {56, 57, 58, 59, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95},
    {59, 66, 67, 68, 87, 96, 97, 98, 91, 99, 100, 101, 95, 102, 103, 104},
    {68, 75, 76, 77, 98, 105, 106, 107, 101, 108, 109, 110, 104, 111, 112, 113},
    {77, 82, 83, 56, 107, 114, 115, 84, 110, 116, 117, 88, 113, 118, 119, 92},
    {120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135},
    {123, 136, 137, 120, 127, 138, 139, 124, 131, 140, 141, 128, 135, 142, 143, 132},
    {132, 133, 134, 135, 144, 145, 146, 147, 148, 149, 150, 151, 68, 152, 153, 154},
    {135, 142, 143, 132, 147, 155, 156, 144, 151, 157, 158, 148, 154, 159, 160, 68},
    {161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176},
    {164, 177, 178, 161, 168, 179, 180, 165, 172, 181, 182, 169, 176, 183, 184, 173},
    {173, 174, 175, 176, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196},
    {176, 183, 184, 173, 188, 197, 198, 185, 192, 199, 200, 189, 196, 201, 202, 193},
    {203, 203, 203, 203, 204, 205, 206, 207, 208, 208, 208, 208, 209, 210, 211, 212},
    {203, 203, 203, 203, 207, 213, 214, 215, 208, 208, 208, 208, 212, 216, 217, 218},
    {203, 203, 203, 203, 215, 219, 220, 221, 208, 208, 208, 208, 218, 222, 223, 224},
    {203, 203, 203, 203, 221, 225, 226, 204, 208, 208, 208, 208, 224, 227, 228, 209},
    {209, 210, 211, 212, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240},
    {212, 216, 217, 218, 232, 241, 242, 243, 236, 244, 245, 246, 240, 247, 248, 249},
    {218, 222, 223, 224, 243, 250, 251, 252, 246, 253, 254, 255, 249, 256, 257, 258},
    {224, 227, 228, 209, 252, 259, 260, 229, 255, 261, 262, 233, 258, 263, 264, 237},
    {265, 265, 265, 265, 266, 267, 268, 269, 270, 271, 272, 273, 92, 119, 118, 113},
    {265, 265, 265, 265, 269, 274, 275, 276, 273, 277, 278, 279, 113, 112, 111, 104},
    {265, 265, 265, 265, 276, 280, 281, 282, 279, 283, 284, 285, 104, 103, 102, 95},
    {265, 265, 265, 265, 282, 286, 287, 266, 285, 288, 289, 270, 95, 94, 93, 92},
};

/// Cubic Bernstein weights at u, and the weights of the derivative d/du.
struct Bernstein {
  std::array<double, 4> b, db;
  explicit Bernstein(double u) {
    const double v = 1.0 - u;
    b = {v * v * v, 3.0 * u * v * v, 3.0 * u * u * v, u * u * u};
    db = {-3.0 * v * v, 3.0 * v * (v - 2.0 * u), 3.0 * u * (2.0 * v - u), 3.0 * u * u};
  }
};

/// A point of the surface with its normal.
struct SurfacePoint {
  P3 position, normal;
};

/// Patch `patch` at (s, t). The normal is dP/dt x dP/ds, the orientation the original writes;
/// it is zero where the patch collapses to a point.
SurfacePoint evaluate(int patch, double s, double t) {
  const Bernstein bs(s), bt(t);
  P3 p, ds, dt;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      const P3 q = kControlPoints[kPatches[patch][4 * r + c]];
      p = p + (bs.b[r] * bt.b[c]) * q;
      ds = ds + (bs.db[r] * bt.b[c]) * q;
      dt = dt + (bs.b[r] * bt.db[c]) * q;
    }
  }
  return {p, normalized(cross(dt, ds))};
}

/// The original's test for the knob and bottom poles: a corner within 1e-4 of the z axis.
bool on_axis(const P3& p) { return std::fabs(p.x) < 1e-4 && std::fabs(p.y) < 1e-4; }

/// Writes a triangle unless two of its corners sit on the pole (it then has no area); a single
/// corner on the pole gets the axis, pointing out of the teapot, as its normal.
void emit_triangle(std::array<SurfacePoint, 3> corners, NffSceneBuilder& out) {
  int on_pole = 0;
  for (SurfacePoint& c : corners) {
    if (!on_axis(c.position)) continue;
    ++on_pole;
    // The lid's pole is above the middle of the teapot, the bottom's below.
    c.normal = {0.0, 0.0, c.position.z > 1.5 ? 1.0 : -1.0};
  }
  if (on_pole > 1) return;
  std::array<Vec3, 3> vertices, normals;
  for (int i = 0; i < 3; ++i) {
    vertices[i] = to_vec3(corners[i].position);
    normals[i] = to_vec3(corners[i].normal);
  }
  out.patch(vertices, normals);
}

/// Each cell (i, j) of the n x n grid, corners numbered (s, t), (s, t+1), (s+1, t+1), (s+1, t),
/// becomes the triangles (0, 1, 2) and (2, 3, 0). The grid's points are evaluated once, where the
/// original evaluates each corner of each triangle: the same values, in a quarter of the time.
void emit_patch(int patch, int n, NffSceneBuilder& out) {
  const auto stride = static_cast<std::size_t>(n) + 1;
  std::vector<SurfacePoint> grid(stride * stride);
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      grid[static_cast<std::size_t>(i) * stride + static_cast<std::size_t>(j)] =
          evaluate(patch, static_cast<double>(i) / n, static_cast<double>(j) / n);
    }
  }
  auto at = [&](int i, int j) { return grid[static_cast<std::size_t>(i) * stride + static_cast<std::size_t>(j)]; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const std::array<SurfacePoint, 4> cell{at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)};
      emit_triangle({cell[0], cell[1], cell[2]}, out);
      emit_triangle({cell[2], cell[3], cell[0]}, out);
    }
  }
}

/// The n x n checkerboard spanning [-4, 4]^2 at z = 0: all white squares, then all grey ones, so
/// that each colour is one material.
void emit_checkerboard(int n, NffSceneBuilder& out) {
  auto coordinate = [n](int k) { return static_cast<float>(4.0 * (2.0 * k / n - 1.0)); };
  for (const int parity : {1, 0}) {
    const float grey = parity == 1 ? 1.f : 0.5f;
    out.fill(lib::surface({grey, grey, grey}, 0.5, 0.5, 30.0, 0.0, 0.0));
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        if ((i + j) % 2 != parity) continue;
        const std::array<Vec3, 4> square{
            Vec3{coordinate(i), coordinate(j), 0.f}, Vec3{coordinate(i + 1), coordinate(j), 0.f},
            Vec3{coordinate(i + 1), coordinate(j + 1), 0.f}, Vec3{coordinate(i), coordinate(j + 1), 0.f}};
        out.polygon(square);
      }
    }
  }
}

void generate(int size, NffSceneBuilder& out) {
  out.background(lib::kSkyBlue);
  out.view(lib::view({4.86, 7.2, 5.4}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0));
  out.light({-3.1f, 9.8f, 12.1f});
  out.light({11.3f, 5.1f, 8.8f});

  emit_checkerboard(size, out);
  out.fill(lib::surface({1.f, 0.5f, 0.1f}, 0.75, 0.25, 37.0, 0.0, 0.0));
  for (int patch = 0; patch < 32; ++patch) emit_patch(patch, size, out);
}

}  // namespace

SpdGenerator teapot() {
  // Size 500 gives 16M teapot triangles (plus 250,000 checker squares), 1.7 GB of scene arrays.
  return {"teapot", "Utah teapot's Bezier patches as smooth triangles on a checkerboard (SPD teapot)", 6, 500,
          generate};
}

}  // namespace raylab::spd
