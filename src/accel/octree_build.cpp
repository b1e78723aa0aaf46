// Octree construction: recursive subdivision at cell centres with exact overlap insertion,
// parallel over subtrees with oneTBB, then flattened into one node array.

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numeric>

#include "raylab/accel/octree.h"
#include "raylab/geometry/overlap.h"

namespace raylab {
namespace {

// Cell enlargement during insertion: 2^-20 of the root edge plus 2^-20 of the largest coordinate
// magnitude. Traversal computes plane crossings within a few float ulps of the root's size and
// of the origin's distance, so a ray can be routed through a cell next to the one a hit lies in
// when the hit is that close to their boundary; the margin puts the primitive in that cell too.
// The coordinate term covers scenes far from the world origin, where the spacing of floats, not
// the scene size, bounds the precision of every plane. Measured with the test that aims rays at
// triangles just inside cell corners (octree_test.cpp, PrimitivesJustInsideACellCorner): hits
// are lost below 2^-25 and none from 2^-24 on, for origins up to 250 scene sizes away; 2^-20
// leaves a factor 16, and costs little: cells reach the margin's width only at depth 20.
constexpr float kRelativeMargin = 0x1p-20f;
constexpr float kCoordinateMargin = 0x1p-20f;

// The root cell's edge in units of the scene's largest extent. Not 1: scenes built on a cube
// and its halves (SPD tetra's tetrahedra are inscribed in the cubes of an octree of the scene's
// bounding cube) would then put their faces and edges exactly on cell planes, and the margin
// would copy every primitive there into the empty cells on the other side (spd:tetra: 7.5
// primitive tests per primary ray with 1.0, 3.4 with 1.1; the cells' extra tenth of empty space
// costs the other scenes nothing measurable, their content boxes cut it away).
constexpr float kRootScale = 1.1f;

// A split that puts every reference into one child is made only for this many references or
// more (see split_pays): enough to be a small object in a large empty cell, which must be
// reached by subdivision, and not a few primitives that meet in a point (a mesh vertex, a
// triangle clipped to the margin's sliver), which would otherwise be followed down to depth L.
constexpr std::size_t kPassThroughItems = 16;

// Nodes with at least this many references classify them and build their children in parallel.
constexpr std::size_t kParallelThreshold = 4096;

struct BuildNode {
  std::vector<std::uint32_t> refs;        // leaf: positions in ids, ascending
  std::unique_ptr<BuildNode[]> children;  // interior: eight, numbered as OctreeNode's
  Box3 content;                           // what its primitives occupy of its enlarged cell
};

class Builder {
 public:
  Builder(const Geometry& geometry, std::span<const std::uint32_t> ids, const OctreeConfig& config, OctreeTree& tree)
      : m_geometry(geometry), m_ids(ids), m_tree(tree) {
    m_max_items = static_cast<std::size_t>(std::max(config.max_items, 0));
    m_max_depth = std::clamp(config.max_depth, 0, kOctreeDepthLimit);
    m_boxes.resize(ids.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size(), 4096), [&](const auto& range) {
      for (std::size_t i = range.begin(); i < range.end(); ++i) m_boxes[i] = geometry.bounds(ids[i]);
    });
    for (const Box3& b : m_boxes) tree.bounds.extend(b);
  }

  void build() {
    m_tree.ids.assign(m_ids.begin(), m_ids.end());
    if (m_ids.empty()) return;
    place_root();
    BuildNode root;
    std::vector<std::uint32_t> all(m_ids.size());
    std::iota(all.begin(), all.end(), 0u);
    const std::uint32_t origin[3] = {0, 0, 0};
    build_node(root, std::move(all), origin, 0);
    m_tree.nodes.push_back({});
    flatten(root, 0, 0);
    m_tree.nodes.shrink_to_fit();  // memory figures count what is kept, not growth slack
    m_tree.refs.shrink_to_fit();
    m_tree.boxes.shrink_to_fit();
  }

 private:
  // The root cell: a cube enclosing the bounds with the margin to spare on every side, so that no
  // primitive lies on its faces and a flat scene still gets a cell of non-zero size. A cube keeps
  // every cell cubic: a box shaped like the scene would split a thin axis as often as a long one,
  // and for a flat scene (a ground plane and what stands on it) every split of the thin axis would
  // copy each reference into both halves. The cube is anchored at the low corner of the bounds,
  // not centred on them: a flat scene then lies just above the bottom face of the cells, instead
  // of on the root's middle plane, where both halves would get all of it.
  void place_root() {
    const Box3& b = m_tree.bounds;
    const Vec3 extent = b.extent();
    const float edge = std::max(extent.x, std::max(extent.y, extent.z));
    const float coord = max_component(max(abs(b.lo), abs(b.hi)));
    float margin = kRelativeMargin * edge + kCoordinateMargin * coord;
    if (!(margin > 0.f)) margin = 1.f;  // everything at the world origin: any size will do
    m_tree.margin = margin;
    m_tree.root_lo = b.lo - Vec3(margin);
    m_tree.root_size = edge * kRootScale + 3.f * margin;  // 2 margins, and one for rounding of the far face
  }

  // Bit a of the result is set when box b reaches the lower (bit 0 of the pair) or upper half of
  // the cell along axis a: a mask of two bits per axis, for the octants the box may touch.
  static int halves_touched(const Box3& b, const float mid_lo[3], const float mid_hi[3], int axis) {
    return (b.lo[axis] <= mid_lo[axis] ? 1 : 0) | (b.hi[axis] >= mid_hi[axis] ? 2 : 0);
  }

  // Which of the eight octants (enlarged by the margin) primitive `ref` overlaps, as a bit mask.
  // Its bounding box decides alone when it reaches a single octant: the primitive overlaps the
  // enlarged parent, and the enlarged octant is the enlarged parent cut by planes the box does
  // not cross. Otherwise each candidate octant gets the exact test.
  std::uint8_t classify(std::uint32_t ref, const Box3 octants[8], const float mid_lo[3], const float mid_hi[3]) const {
    const Box3& b = m_boxes[ref];
    const int hx = halves_touched(b, mid_lo, mid_hi, 0), hy = halves_touched(b, mid_lo, mid_hi, 1),
              hz = halves_touched(b, mid_lo, mid_hi, 2);
    int candidates = 0;
    for (int c = 0; c < 8; ++c) {
      if ((hx >> (c & 1) & 1) && (hy >> (c >> 1 & 1) & 1) && (hz >> (c >> 2 & 1) & 1)) candidates |= 1 << c;
    }
    if ((candidates & (candidates - 1)) == 0) return static_cast<std::uint8_t>(candidates);
    int result = 0;
    for (int c = 0; c < 8; ++c) {
      if ((candidates >> c & 1) && overlaps_box(m_geometry, m_ids[ref], octants[c])) result |= 1 << c;
    }
    return static_cast<std::uint8_t>(result);
  }

  // The union of the bounds of primitives `refs`, each clipped to `cell` (the enlarged cell they
  // were inserted into): every point where a ray can hit one of them inside the cell lies in it.
  Box3 content_box(const std::vector<std::uint32_t>& refs, const Box3& cell) const {
    Box3 content;
    for (const std::uint32_t r : refs) content.extend(Box3{max(m_boxes[r].lo, cell.lo), min(m_boxes[r].hi, cell.hi)});
    return content;
  }

  void build_node(BuildNode& node, std::vector<std::uint32_t> refs, const std::uint32_t lo[3], int depth) {
    const std::size_t n = refs.size();
    const Box3 cell = m_tree.cell_box(lo, depth);
    node.content = content_box(refs, {cell.lo - Vec3(m_tree.margin), cell.hi + Vec3(m_tree.margin)});
    if (n <= m_max_items || depth >= m_max_depth) {
      node.refs = std::move(refs);
      return;
    }
    const std::uint32_t half = kOctreeLatticeSteps >> (depth + 1);
    const float margin = m_tree.margin;
    Box3 octants[8];
    std::uint32_t child_lo[8][3];
    for (int c = 0; c < 8; ++c) {
      for (int a = 0; a < 3; ++a) child_lo[c][a] = lo[a] + ((c >> a & 1) ? half : 0);
      const Box3 cell = m_tree.cell_box(child_lo[c], depth + 1);
      octants[c] = {cell.lo - Vec3(margin), cell.hi + Vec3(margin)};
    }
    float mid_lo[3], mid_hi[3];  // the planes bounding the enlarged lower and upper octants
    for (int a = 0; a < 3; ++a) {
      mid_lo[a] = octants[0].hi[a];
      mid_hi[a] = octants[7].lo[a];
    }

    std::vector<std::uint8_t> masks(n);
    auto classify_range = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) masks[i] = classify(refs[i], octants, mid_lo, mid_hi);
    };
    if (n >= kParallelThreshold) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024),
                        [&](const auto& range) { classify_range(range.begin(), range.end()); });
    } else {
      classify_range(0, n);
    }
    std::array<std::size_t, 8> counts{};
    std::array<Box3, 8> contents;
    for (std::size_t i = 0; i < n; ++i) {
      const Box3& b = m_boxes[refs[i]];
      for (int c = 0; c < 8; ++c) {
        if (masks[i] >> c & 1) {
          ++counts[c];
          contents[c].extend(Box3{max(b.lo, octants[c].lo), min(b.hi, octants[c].hi)});
        }
      }
    }
    if (!octree_split_pays(n, node.content, counts, contents)) {
      node.refs = std::move(refs);
      return;
    }

    std::array<std::vector<std::uint32_t>, 8> child_refs;
    for (int c = 0; c < 8; ++c) child_refs[c].reserve(counts[c]);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 8; ++c)
        if (masks[i] >> c & 1) child_refs[c].push_back(refs[i]);
    refs = {};
    masks = {};

    node.children = std::make_unique<BuildNode[]>(8);
    auto build_child = [&](int c) { build_node(node.children[c], std::move(child_refs[c]), child_lo[c], depth + 1); };
    if (n >= kParallelThreshold) {
      tbb::parallel_for(0, 8, build_child);
    } else {
      for (int c = 0; c < 8; ++c) build_child(c);
    }
  }

  // Depth first: a node's eight children are appended together, then each child's subtree.
  void flatten(const BuildNode& node, std::size_t index, int depth) {
    if (!node.children) {
      m_tree.nodes[index] = {static_cast<std::uint32_t>(m_tree.refs.size()),
                             static_cast<std::uint32_t>(node.refs.size())};
      m_tree.refs.insert(m_tree.refs.end(), node.refs.begin(), node.refs.end());
      ++m_tree.leaf_count;
      m_tree.max_depth = std::max(m_tree.max_depth, depth);
      return;
    }
    const std::size_t first = m_tree.nodes.size();
    m_tree.nodes[index] = {static_cast<std::uint32_t>(first), OctreeNode::kInterior};
    m_tree.nodes.resize(first + 8);
    OctreeChildBoxes& boxes = m_tree.boxes.emplace_back();  // entry (first - 1) / 8: groups are appended in step
    for (int c = 0; c < 8; ++c) {
      for (int a = 0; a < 3; ++a) {
        boxes.lo[a][c] = node.children[c].content.lo[a];
        boxes.hi[a][c] = node.children[c].content.hi[a];
      }
    }
    for (int c = 0; c < 8; ++c) flatten(node.children[c], first + c, depth + 1);
  }

  const Geometry& m_geometry;
  std::span<const std::uint32_t> m_ids;
  OctreeTree& m_tree;
  std::vector<Box3> m_boxes;  // bounds of each primitive, by position in ids
  std::size_t m_max_items = 0;
  int m_max_depth = 0;
};

}  // namespace

// A split that leaves every reference in one child with the same box changes nothing for a ray
// but one more node to enter, and it is made for kPassThroughItems references or more: it is how
// the cells reach the size of a small object in a large empty cell.
//
// A split that leaves every reference in two or more children separates nothing either, and is
// never made. The area terms alone would make it along a line that more than K primitives share
// (an edge of many faces, degenerate triangles on one segment): the two children along the line
// keep all n references in boxes of a quarter of the area each, 1 + n / 2 < n, at every level,
// so the cells along the line doubled per level down to depth L (found by the accel fuzz target:
// 14 such triangles made 1.9 M nodes and 80 MB in 6 s). Around a point the same split is cheaper
// (eight cells per level) but no more useful.
bool octree_split_pays(std::size_t n, const Box3& content, const std::array<std::size_t, 8>& counts,
                       const std::array<Box3, 8>& contents) {
  const double area = content.area();
  int nonempty = 0, keeping_all = 0;
  double expected = kOctreeTraversalCost;
  for (int c = 0; c < 8; ++c) {
    if (counts[c] == 0) continue;
    ++nonempty;
    if (counts[c] == n) ++keeping_all;
    // A flat or degenerate content (area 0) gives no probabilities: count every reference.
    expected += area > 0.0 ? double(counts[c]) * contents[c].area() / area : double(counts[c]);
  }
  if (nonempty == 1) return n >= kPassThroughItems;
  if (keeping_all >= 2) return false;
  return expected < double(n);
}

OctreeTree build_octree(const Geometry& geometry, const OctreeConfig& config) {
  const std::vector<std::uint32_t> ids = geometry.primitive_ids();
  return build_octree(geometry, ids, config);
}

OctreeTree build_octree(const Geometry& geometry, std::span<const std::uint32_t> ids, const OctreeConfig& config) {
  OctreeTree tree;
  Builder builder(geometry, ids, config, tree);
  builder.build();
  return tree;
}

}  // namespace raylab
