#include "raylab/geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace raylab {
namespace {

// Work is done in double on coordinates relative to the first vertex: differences of float
// inputs are then (nearly always) exact and the orientation products of them are exact, so the
// sign tests below are reliable for the collinear and touching configurations that scene files
// produce by construction.
struct Point2 {
  double x = 0.0, y = 0.0;
};

bool operator==(Point2 a, Point2 b) { return a.x == b.x && a.y == b.y; }

// Twice the signed area of triangle abc: > 0 when counter-clockwise.
double orient(Point2 a, Point2 b, Point2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Newell normal in double. Summing cross(p_i - p_0, p_{i+1} - p_0) gives the same vector as the
// textbook formula but without the cancellation that far-from-origin coordinates cause.
std::array<double, 3> newell(std::span<const Vec3> v) {
  std::array<double, 3> n{0.0, 0.0, 0.0};
  if (v.size() < 3) return n;
  auto rel = [&](std::size_t i) -> std::array<double, 3> {
    return {double(v[i].x) - double(v[0].x), double(v[i].y) - double(v[0].y), double(v[i].z) - double(v[0].z)};
  };
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const auto a = rel(i), b = rel(i + 1);
    n[0] += a[1] * b[2] - a[2] * b[1];
    n[1] += a[2] * b[0] - a[0] * b[2];
    n[2] += a[0] * b[1] - a[1] * b[0];
  }
  return n;
}

// Where the ring's points lie: a uniform grid of cells over their bounding box, each listing
// the ring positions in it, so that an ear test looks only at the points inside its triangle's
// box instead of at every remaining point. It finds what the full scan finds: a point inside the
// triangle (boundary included) lies inside the triangle's box, and a cell is a monotone function
// of the coordinates, so the cells from the box's low corner to its high corner hold every point
// in the box.
class PointGrid {
 public:
  PointGrid(const std::vector<Point2>& pts, const std::vector<std::uint32_t>& ring) {
    const std::size_t m = ring.size();
    m_lo = m_hi = pts[ring[0]];
    for (const std::uint32_t i : ring) {
      m_lo = {std::min(m_lo.x, pts[i].x), std::min(m_lo.y, pts[i].y)};
      m_hi = {std::max(m_hi.x, pts[i].x), std::max(m_hi.y, pts[i].y)};
    }
    // About one point a cell: enough cells that an ear's box holds few points, few enough that
    // a large ear's box does not walk many empty cells.
    m_side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(m))));
    m_scale_x = scale(m_hi.x - m_lo.x);
    m_scale_y = scale(m_hi.y - m_lo.y);
    m_first.assign(static_cast<std::size_t>(m_side) * m_side + 1, 0);
    std::vector<std::uint32_t> cell_of(m);
    for (std::uint32_t k = 0; k < m; ++k) {
      cell_of[k] = cell(pts[ring[k]]);
      ++m_first[cell_of[k] + 1];
    }
    for (std::size_t c = 1; c < m_first.size(); ++c) m_first[c] += m_first[c - 1];
    m_positions.resize(m);
    std::vector<std::uint32_t> fill(m_first.begin(), m_first.end() - 1);
    for (std::uint32_t k = 0; k < m; ++k) m_positions[fill[cell_of[k]]++] = k;
  }

  /// Calls `visit(k)` for the ring positions k in the cells that cover the box [lo, hi] (a
  /// superset of the points in it) until a call returns true; returns whether one did.
  template <class Visit>
  bool any_near(Point2 lo, Point2 hi, Visit&& visit) const {
    const int x0 = axis_cell(lo.x, m_lo.x, m_scale_x), x1 = axis_cell(hi.x, m_lo.x, m_scale_x);
    const int y0 = axis_cell(lo.y, m_lo.y, m_scale_y), y1 = axis_cell(hi.y, m_lo.y, m_scale_y);
    for (int y = y0; y <= y1; ++y) {
      const std::size_t row = static_cast<std::size_t>(y) * m_side;
      for (std::uint32_t j = m_first[row + x0]; j < m_first[row + x1 + 1]; ++j) {
        if (visit(m_positions[j])) return true;
      }
    }
    return false;
  }

 private:
  // Cells per unit length along an axis of extent `extent` (0 when flat or too thin to divide).
  double scale(double extent) const {
    const double s = extent > 0.0 ? static_cast<double>(m_side) / extent : 0.0;
    return std::isfinite(s) ? s : 0.0;
  }
  int axis_cell(double v, double lo, double scale) const {
    const double c = (v - lo) * scale;  // >= 0 for v >= lo, and non-decreasing in v
    return c >= static_cast<double>(m_side) ? m_side - 1 : static_cast<int>(c);
  }
  std::uint32_t cell(Point2 p) const {
    return static_cast<std::uint32_t>(axis_cell(p.y, m_lo.y, m_scale_y) * m_side + axis_cell(p.x, m_lo.x, m_scale_x));
  }

  Point2 m_lo, m_hi;
  int m_side = 1;
  double m_scale_x = 0.0, m_scale_y = 0.0;
  std::vector<std::uint32_t> m_first;      // cell c's positions: m_positions[m_first[c], m_first[c + 1])
  std::vector<std::uint32_t> m_positions;  // ring positions, cell by cell (a row's cells adjacent)
};

}  // namespace

Vec3 polygon_normal(std::span<const Vec3> vertices) {
  const auto n = newell(vertices);
  return {float(n[0]), float(n[1]), float(n[2])};
}

std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const Vec3> vertices) {
  return detail::triangulate_polygon(vertices, detail::kPointGridFrom);
}

std::vector<std::array<std::uint32_t, 3>> detail::triangulate_polygon(std::span<const Vec3> vertices,
                                                                      std::size_t grid_from) {
  using Tri = std::array<std::uint32_t, 3>;
  std::vector<Tri> out;
  const std::size_t n = vertices.size();
  if (n < 3 || n > std::numeric_limits<std::uint32_t>::max()) return out;

  const auto normal = newell(vertices);
  if (!std::isfinite(normal[0]) || !std::isfinite(normal[1]) || !std::isfinite(normal[2])) return out;
  if (normal[0] == 0.0 && normal[1] == 0.0 && normal[2] == 0.0) return out;  // zero area
  // Triangles are by far the most common face: skip the allocations below.
  if (n == 3) return {Tri{0, 1, 2}};

  // Project by dropping the dominant axis. Keeping the other two in cyclic order (y,z / z,x /
  // x,y) makes the projected signed area equal to that Newell component; mirroring one axis when
  // it is negative makes every polygon counter-clockwise, so "convex" is always "left turn".
  const std::array<double, 3> mag{std::fabs(normal[0]), std::fabs(normal[1]), std::fabs(normal[2])};
  const int axis = mag[0] > mag[1] ? (mag[0] > mag[2] ? 0 : 2) : (mag[1] > mag[2] ? 1 : 2);
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  const double mirror = normal[axis] < 0.0 ? -1.0 : 1.0;
  std::vector<Point2> pts(n);
  for (std::size_t i = 0; i < n; ++i) {
    pts[i] = {mirror * (double(vertices[i][a1]) - double(vertices[0][a1])),
              double(vertices[i][a2]) - double(vertices[0][a2])};
  }

  // The ring of remaining vertices, without consecutive repeats (their zero-length edges would
  // make every neighbouring ear test degenerate). The first of a run of repeats is kept.
  std::vector<std::uint32_t> ring;
  ring.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (ring.empty() || !(pts[i] == pts[ring.back()])) ring.push_back(i);
  }
  while (ring.size() > 1 && pts[ring.back()] == pts[ring.front()]) ring.pop_back();
  const std::size_t m = ring.size();
  if (m < 3) return out;
  out.reserve(m - 2);

  // Doubly linked list over ring positions; removal is O(1).
  std::vector<std::uint32_t> prev(m), next(m);
  for (std::size_t k = 0; k < m; ++k) {
    prev[k] = std::uint32_t(k == 0 ? m - 1 : k - 1);
    next[k] = std::uint32_t(k + 1 == m ? 0 : k + 1);
  }
  auto at = [&](std::uint32_t k) { return pts[ring[k]]; };
  auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { out.push_back({ring[a], ring[b], ring[c]}); };

  // An ear is a strictly convex vertex whose triangle holds no other remaining vertex, boundary
  // included: a vertex on the new diagonal would leave the rest of the polygon touching itself,
  // and collinear (straight-angle) vertices are never ears, so they end up inside proper
  // triangles instead of in zero-area ones. Vertices at the same place as the ear's base corners
  // are skipped: a polygon that touches itself there (keyhole bridges) cannot cut the ear without
  // also putting a vertex inside it.
  // Large polygons look only at the points near the ear (PointGrid), skipping the clipped ones
  // and the ear's own three corners: the same points the ring walk below visits, less those
  // outside the ear's box, which cannot be in it.
  const std::optional<PointGrid> grid =
      m >= grid_from ? std::optional<PointGrid>(std::in_place, pts, ring) : std::nullopt;
  std::vector<char> clipped(grid ? m : 0);
  auto is_ear = [&](std::uint32_t k) {
    const Point2 a = at(prev[k]), b = at(k), c = at(next[k]);
    if (orient(a, b, c) <= 0.0) return false;
    auto holds = [&](Point2 p) {
      if (p == a || p == c) return false;
      return orient(a, b, p) >= 0.0 && orient(b, c, p) >= 0.0 && orient(c, a, p) >= 0.0;
    };
    if (grid) {
      const Point2 lo{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y})};
      const Point2 hi{std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y})};
      return !grid->any_near(lo, hi, [&](std::uint32_t q) {
        return !clipped[q] && q != k && q != prev[k] && q != next[k] && holds(at(q));
      });
    }
    for (std::uint32_t q = next[next[k]]; q != prev[k]; q = next[q]) {
      if (holds(at(q))) return false;
    }
    return true;
  };

  // Ear flags are cached and only the two neighbours of a clipped ear are re-tested: for a simple
  // polygon no other vertex can change status (a clipped ear is convex, and a triangle holding
  // any vertex also holds a reflex one, which stays). That keeps the work O(n^2). Input that is not
  // simple can break that argument, so when a full turn finds no ear the flags are recomputed
  // once before giving up. The budget of ear tests (each O(n)) bounds the total work at O(n^2)
  // whatever the input.
  std::vector<char> ear(m);
  for (std::uint32_t k = 0; k < m; ++k) ear[k] = is_ear(k);
  std::size_t tests = m;
  const std::size_t budget = 8 * m;
  std::size_t remaining = m;
  // Starting at the second vertex and moving on to the next after each clip makes a convex
  // polygon come out as the fan (0, k, k + 1) that the OBJ loader used to produce, so meshes of
  // convex faces triangulate (and render) exactly as before.
  std::uint32_t k = 1;
  std::size_t since_clip = 0;  // vertices looked at since the last clip
  bool refreshed = false;      // flags recomputed since the last clip
  while (remaining > 3) {
    if (ear[k]) {
      const std::uint32_t p = prev[k], q = next[k];
      emit(p, k, q);
      if (grid) clipped[k] = 1;
      next[p] = q;
      prev[q] = p;
      --remaining;
      ear[p] = is_ear(p);
      ear[q] = is_ear(q);
      tests += 2;
      k = q;
      since_clip = 0;
      refreshed = false;
      continue;
    }
    k = next[k];
    if (++since_clip < remaining) continue;
    if (refreshed || tests + remaining > budget) break;  // no ear: fan below
    std::uint32_t j = k;
    do {
      ear[j] = is_ear(j);
      j = next[j];
    } while (j != k);
    tests += remaining;
    since_clip = 0;
    refreshed = true;
  }
  // Either the last triangle (prev, k, next) or, when no ear was found, a fan over what is left:
  // the input was not simple, and any answer with valid indices beats none.
  const std::uint32_t hub = prev[k];
  for (std::uint32_t j = next[hub]; next[j] != hub; j = next[j]) emit(hub, j, next[j]);
  return out;
}

}  // namespace raylab
