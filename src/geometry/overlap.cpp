#include "raylab/geometry/overlap.h"

#include <algorithm>
#include <array>
#include <cmath>

// All tests run in double on coordinates taken relative to a point near the box, so that the
// float inputs lose nothing and the remaining rounding (relative 1e-16) is far below the slack
// each test allows itself (relative 1e-12 to 1e-9): a rejection is then always a real one.

namespace raylab {
namespace {

// A double 3-vector, local to these tests.
struct D3 {
  double x = 0.0, y = 0.0, z = 0.0;
  double operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
};
D3 d3(Vec3 v) { return {v.x, v.y, v.z}; }
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
D3 abs(D3 a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }
double max_abs(D3 a) { return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}); }
D3 unit_axis(int k) { return {k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0}; }

// Relative slack of the separating axis tests (projections are accurate to ~1e-15).
constexpr double kSatSlack = 1e-12;

// A box as centre and half extents in double.
struct CenteredBox {
  D3 center, half;
  explicit CenteredBox(const Box3& b)
      : center{0.5 * (double(b.lo.x) + b.hi.x), 0.5 * (double(b.lo.y) + b.hi.y), 0.5 * (double(b.lo.z) + b.hi.z)},
        half{0.5 * (double(b.hi.x) - b.lo.x), 0.5 * (double(b.hi.y) - b.lo.y), 0.5 * (double(b.hi.z) - b.lo.z)} {}
};

// Separating axis test of a convex polygon (vertices relative to the box centre, edge directions)
// against a box of half extents `half` centred at the origin. The axes: the 3 box normals, the
// polygon normal and each edge direction crossed with each box axis. An axis that comes out zero
// (a degenerate polygon) projects everything to 0 and so separates nothing: it is skipped without
// a branch, and what remains is the complete axis set of the segment or point the polygon became.
template <std::size_t kVerts, std::size_t kEdges>
bool polygon_overlaps_centered_box(const std::array<D3, kVerts>& v, const std::array<D3, kEdges>& edges, D3 half) {
  double scale = max_abs(half);
  for (const D3& p : v) scale = std::max(scale, max_abs(p));
  const double slack = kSatSlack * scale;
  auto separated = [&](D3 axis) {
    double lo = dot(axis, v[0]), hi = lo;
    for (std::size_t i = 1; i < kVerts; ++i) {
      const double p = dot(axis, v[i]);
      lo = std::min(lo, p);
      hi = std::max(hi, p);
    }
    const D3 a = abs(axis);
    const double r = dot(half, a) + slack * (a.x + a.y + a.z);
    return lo > r || hi < -r;
  };
  for (int k = 0; k < 3; ++k) {
    if (separated(unit_axis(k))) return false;
  }
  for (const D3& e : edges) {
    for (int k = 0; k < 3; ++k) {
      if (separated(cross(e, unit_axis(k)))) return false;
    }
  }
  return !separated(cross(edges[0], edges[1]));
}

// Squared distances from `c` to the nearest and the farthest point of `box`.
void box_distances2(D3 c, const Box3& box, double& near2, double& far2) {
  near2 = far2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double lo = double(box.lo[k]) - c[k], hi = double(box.hi[k]) - c[k];
    const double near = lo > 0.0 ? lo : hi < 0.0 ? -hi : 0.0;
    const double far = std::max(std::fabs(lo), std::fabs(hi));
    near2 += near * near;
    far2 += far * far;
  }
}

bool boxes_overlap(const Box3& a, const Box3& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

// ---------------------------------------------------------------------------------------------
// Cone frustum

// Relative slack of the cone test: its line search and bounds are accurate to far better.
constexpr double kConeSlack = 1e-9;
// Frank-Wolfe steps before an undecided box is accepted, and golden-section steps per line search.
constexpr int kConeSteps = 16;
constexpr int kLineSearchSteps = 28;

// The cone frustum in its axis frame, relative to its base point: f(p) = |p - (p.w) w| - r(p.w),
// zero on the (infinitely extended) lateral surface, negative inside, and convex.
struct ConeFrame {
  D3 w;           // unit axis
  double length;  // base to apex
  double r0;      // radius at the base
  double slope;   // radius change per unit height
  double f(D3 p) const {
    const double z = dot(p, w);
    const D3 q = p - w * z;
    return std::sqrt(dot(q, q)) - (r0 + slope * z);
  }
  // A subgradient of f at p: the radial direction, tilted by the slope. On the axis the radial
  // part is any vector of length <= 1; 0 is one.
  D3 gradient(D3 p) const {
    const D3 q = p - w * dot(p, w);
    const double len = std::sqrt(dot(q, q));
    const D3 radial = len > 0.0 ? q * (1.0 / len) : D3{};
    return radial - w * slope;
  }
};

// Vertices of the box (relative to the cone's base) cut to the slab zlo <= p.w <= zhi: the corners
// inside it and the points where box edges cross its two planes (at most 8 + 24). Returns the count.
int clipped_box_vertices(const D3 corner[8], D3 w, double zlo, double zhi, std::array<D3, 32>& out) {
  double z[8];
  int n = 0;
  for (int i = 0; i < 8; ++i) {
    z[i] = dot(corner[i], w);
    if (z[i] >= zlo && z[i] <= zhi) out[n++] = corner[i];
  }
  for (int i = 0; i < 8; ++i) {
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (i & bit) continue;
      const int j = i | bit;  // the edge i-j runs along one axis
      for (double plane : {zlo, zhi}) {
        if ((z[i] - plane) * (z[j] - plane) < 0.0) {
          const double s = (plane - z[i]) / (z[j] - z[i]);
          out[n++] = corner[i] + (corner[j] - corner[i]) * s;
        }
      }
    }
  }
  return n;
}

// Minimum of the convex f on the segment a-b by golden-section search; returns the best point.
D3 line_minimum(const ConeFrame& cone, D3 a, D3 b, double& f_best) {
  constexpr double kInvPhi = 0.6180339887498949;
  double lo = 0.0, hi = 1.0;
  double x1 = hi - kInvPhi, x2 = lo + kInvPhi;
  double f1 = cone.f(a + (b - a) * x1), f2 = cone.f(a + (b - a) * x2);
  for (int i = 0; i < kLineSearchSteps; ++i) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - kInvPhi * (hi - lo);
      f1 = cone.f(a + (b - a) * x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + kInvPhi * (hi - lo);
      f2 = cone.f(a + (b - a) * x2);
    }
  }
  const double s = f1 <= f2 ? x1 : x2;
  f_best = std::min(f1, f2);
  return a + (b - a) * s;
}

}  // namespace

bool triangle_overlaps_box(const Triangle& t, const Box3& box) {
  if (box.empty()) return false;
  const CenteredBox b(box);
  const std::array<D3, 3> v = {d3(t.p0) - b.center, d3(t.p1) - b.center, d3(t.p2) - b.center};
  const std::array<D3, 3> edges = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  return polygon_overlaps_centered_box(v, edges, b.half);
}

bool quad_overlaps_box(const Quad& q, const Box3& box) {
  if (box.empty()) return false;
  const CenteredBox b(box);
  const D3 c = d3(q.corner) - b.center, u = d3(q.edge_u), w = d3(q.edge_v);
  // Corners in double: the parallelogram intersect_quad tests, without rounding its far corners.
  const std::array<D3, 4> v = {c, c + u, c + u + w, c + w};
  const std::array<D3, 2> edges = {u, w};
  return polygon_overlaps_centered_box(v, edges, b.half);
}

bool sphere_overlaps_box(const Sphere& s, const Box3& box) {
  if (box.empty()) return false;
  double near2 = 0.0, far2 = 0.0;
  box_distances2(d3(s.center), box, near2, far2);
  const double r2 = double(s.radius) * s.radius;
  const double slack = kSatSlack * (far2 + r2);
  return near2 <= r2 + slack && far2 >= r2 - slack;
}

bool ball_overlaps_box(const Sphere& s, const Box3& box) {
  if (box.empty()) return false;
  double near2 = 0.0, far2 = 0.0;
  box_distances2(d3(s.center), box, near2, far2);
  const double r2 = double(s.radius) * s.radius;
  return near2 <= r2 + kSatSlack * (far2 + r2);
}

bool disk_overlaps_box(const Disk& d, const Box3& box) {
  if (box.empty()) return false;
  const D3 n = d3(d.normal);
  if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) return false;  // intersect_disk never hits it
  // The box relative to the centre: [a, b]. The point of box-and-plane nearest the centre minimises
  // |x|^2 subject to a <= x <= b and n.x = 0; it is x(l) = clamp(l n, a, b) for the l at which
  // g(l) = n.x(l), a non-decreasing piecewise-linear function, crosses 0 (the Lagrange condition).
  const D3 c = d3(d.center);
  const D3 a = d3(box.lo) - c, b = d3(box.hi) - c;
  const double scale = std::max({max_abs(a), max_abs(b), std::fabs(double(d.radius))});
  const double slack = kSatSlack * scale * (std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z));
  auto x_of = [&](double l) {
    return D3{std::clamp(l * n.x, a.x, b.x), std::clamp(l * n.y, a.y, b.y), std::clamp(l * n.z, a.z, b.z)};
  };
  // The breakpoints of g: where a component of l n meets a face of the box.
  std::array<double, 6> bp{};
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    if (n[k] != 0.0) bp[count++] = a[k] / n[k], bp[count++] = b[k] / n[k];
  }
  std::sort(bp.begin(), bp.begin() + count);
  // Below the first breakpoint g is its minimum over the box, above the last its maximum.
  D3 x;
  const double g_first = dot(n, x_of(bp[0])), g_last = dot(n, x_of(bp[count - 1]));
  if (g_first > slack || g_last < -slack) return false;  // the plane misses the box
  if (g_first >= 0.0) {
    x = x_of(bp[0]);
  } else if (g_last <= 0.0) {
    x = x_of(bp[count - 1]);
  } else {
    double l = bp[count - 1];
    for (int i = 1; i < count; ++i) {
      const double g0 = dot(n, x_of(bp[i - 1])), g1 = dot(n, x_of(bp[i]));
      if (g1 >= 0.0) {  // g is linear between the two breakpoints, g0 < 0 <= g1
        l = bp[i - 1] + (bp[i] - bp[i - 1]) * (-g0 / (g1 - g0));
        break;
      }
    }
    x = x_of(l);
  }
  const double r2 = double(d.radius) * d.radius;
  return dot(x, x) <= r2 + 1e-10 * (r2 + scale * scale);
}

bool cylinder_overlaps_box(const Cylinder& c, const Box3& box) {
  if (box.empty()) return false;
  const Vec3 axis_f = c.apex - c.base;
  if (dot(axis_f, axis_f) == 0.f) return false;  // intersect_cylinder never hits a zero-length one
  const D3 base = d3(c.base), axis = d3(c.apex) - base;
  ConeFrame cone;
  cone.length = std::sqrt(dot(axis, axis));
  cone.w = axis * (1.0 / cone.length);
  cone.r0 = c.base_radius;
  cone.slope = (double(c.apex_radius) - c.base_radius) / cone.length;
  const D3 lo = d3(box.lo) - base, hi = d3(box.hi) - base;
  const double rmax = std::max(std::fabs(double(c.base_radius)), std::fabs(double(c.apex_radius)));
  const double tol = kConeSlack * std::max({max_abs(lo), max_abs(hi), cone.length, rmax});

  // 1. The bounds of the two end circles hold the surface: a cheap exact-axis rejection.
  for (int k = 0; k < 3; ++k) {
    const double e = std::sqrt(std::max(0.0, 1.0 - cone.w[k] * cone.w[k]));
    const double e0 = std::fabs(double(c.base_radius)) * e, e1 = std::fabs(double(c.apex_radius)) * e;
    if (hi[k] < std::min(-e0, axis[k] - e1) - tol || lo[k] > std::max(e0, axis[k] + e1) + tol) return false;
  }

  // 2. The part of the box between the end planes, as the vertices of its convex polytope Q.
  D3 corner[8];
  for (int i = 0; i < 8; ++i) corner[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
  std::array<D3, 32> q;
  const int n = clipped_box_vertices(corner, cone.w, -tol, cone.length + tol, q);
  if (n == 0) return false;  // the box lies wholly beyond one end

  // 3. f at the vertices. Q is connected, so a sign change means f = 0 somewhere in it. The
  //    maximum of the convex f is at a vertex: all negative means Q is inside the cone.
  double f_min = cone.f(q[0]), f_max = f_min;
  int best = 0;
  for (int i = 1; i < n; ++i) {
    const double f = cone.f(q[i]);
    if (f < f_min) f_min = f, best = i;
    f_max = std::max(f_max, f);
  }
  if (f_max < -tol) return false;
  if (f_min <= tol) return true;

  // 4. Every vertex outside: is min f over Q > 0? Frank-Wolfe from the best vertex. At each point
  //    x the subgradient plane gives min f >= f(x) + min over vertices of g.(v - x), a certificate
  //    when positive; else a line search towards that vertex finds a lower x.
  D3 x = q[best];
  double fx = f_min;
  for (int step = 0; step < kConeSteps; ++step) {
    const D3 g = cone.gradient(x);
    int s = 0;
    double gs = dot(g, q[0]);
    for (int i = 1; i < n; ++i) {
      const double d = dot(g, q[i]);
      if (d < gs) gs = d, s = i;
    }
    if (fx + (gs - dot(g, x)) > tol) return false;
    double f_line = fx;
    const D3 next = line_minimum(cone, x, q[s], f_line);
    if (f_line <= tol) return true;
    if (f_line < fx) x = next, fx = f_line;
  }
  return true;  // undecided after kConeSteps: accept, the safe answer
}

bool overlaps_box(const Geometry& geometry, std::uint32_t prim_id, const Box3& box) {
  if (prim_id >= kGroupIdBase) {
    const GroupShape& g = geometry.groups[prim_id - kGroupIdBase];
    if (!boxes_overlap(g.box, box)) return false;
    return g.sphere.radius < 0.f || ball_overlaps_box(g.sphere, box);
  }
  const ShapeRef r = geometry.resolve(prim_id);
  switch (r.kind) {
    case ShapeKind::kTriangle:
      return triangle_overlaps_box(geometry.triangles[r.index], box);
    case ShapeKind::kSphere:
      return sphere_overlaps_box(geometry.spheres[r.index], box);
    case ShapeKind::kCylinder:
      return cylinder_overlaps_box(geometry.cylinders[r.index], box);
    case ShapeKind::kDisk:
      return disk_overlaps_box(geometry.disks[r.index], box);
    case ShapeKind::kQuad:
      return quad_overlaps_box(geometry.quads[r.index], box);
  }
  return true;
}

}  // namespace raylab
