// Merging the irregular grid's cells. Along one axis at a time, cells whose boxes share a face
// and have the same extent on the two other axes form chains; each chain is merged greedily from
// its low end: the cell built so far absorbs its neighbour when the merged cell is no more
// expensive to cross than the two apart. The cost of a cell is its surface area (how likely a
// ray is to cross it) times the work a ray does there, cost(c) = area(c) * (C_step + C_prim *
// |refs(c)|). Two empty cells always merge (a longer empty cell is a longer step), and so do two
// cells with the same references. Chains are disjoint, so they merge in parallel.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <iterator>
#include <vector>

#include <tbb/parallel_for.h>

#include "irregular_grid_build.h"

namespace raylab {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// Half the surface area of lattice box `b`, in world units.
float half_area(const IrregularGridData& data, const std::array<std::uint16_t, 6>& b) {
  float e[3];
  for (int a = 0; a < 3; ++a) e[a] = data.plane(a, b[a + 3]) - data.plane(a, b[a]);
  return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
}

// Sorted union of `a` and `b` into `out`.
void unite(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b, std::vector<std::uint32_t>& out) {
  out.clear();
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
}

// One merge pass along `axis`; returns whether anything merged.
bool merge_pass(IrregularBuildCells& cells, IrregularGridData& data, const IrregularGridConfig& config, int axis) {
  const std::size_t n = cells.size();
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  // The neighbour across each cell's upper face along the axis, when it matches exactly.
  std::vector<std::uint32_t> next(n, kNone);
  std::vector<std::uint8_t> has_prev(n, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const auto& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      const auto& b = cells.boxes[c];
      if (b[axis + 3] >= data.lattice[axis]) continue;
      std::uint32_t p[3] = {b[0], b[1], b[2]};
      p[axis] = b[axis + 3];
      const std::uint32_t m = data.cell_at(p[0], p[1], p[2]);
      const auto& nb = cells.boxes[m];
      if (nb[axis] != b[axis + 3] || nb[u] != b[u] || nb[v] != b[v] || nb[u + 3] != b[u + 3] || nb[v + 3] != b[v + 3])
        continue;
      next[c] = m;
      has_prev[m] = 1;  // a cell has at most one such predecessor: the one behind its lower face
    }
  });

  // Greedy merging along each chain: leader[c] is the first cell of the group c joins.
  const float c_step = config.step_cost, c_prim = config.prim_cost;
  std::vector<std::uint32_t> leader(n), size(n, 0u);
  std::atomic<bool> merged{false};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& r) {
    std::vector<std::uint32_t> acc, joined;
    for (std::size_t head = r.begin(); head != r.end(); ++head) {
      if (has_prev[head]) continue;
      std::uint32_t lead = static_cast<std::uint32_t>(head);
      auto box = cells.boxes[head];
      auto refs = cells.refs_of(head);
      acc.assign(refs.begin(), refs.end());
      float cost = half_area(data, box) * (c_step + c_prim * float(acc.size()));
      leader[head] = lead;
      for (std::uint32_t c = next[head]; c != kNone; c = next[c]) {
        size[lead] = static_cast<std::uint32_t>(acc.size());
        const auto nb = cells.refs_of(c);
        const float nb_cost = half_area(data, cells.boxes[c]) * (c_step + c_prim * float(nb.size()));
        auto both = box;
        both[axis + 3] = cells.boxes[c][axis + 3];
        unite(acc, nb, joined);
        const float both_cost = half_area(data, both) * (c_step + c_prim * float(joined.size()));
        if (both_cost <= cost + nb_cost) {
          leader[c] = lead;
          box = both;
          acc.swap(joined);
          cost = both_cost;
          merged.store(true, std::memory_order_relaxed);
        } else {
          lead = c;
          leader[c] = c;
          box = cells.boxes[c];
          acc.assign(nb.begin(), nb.end());
          cost = nb_cost;
        }
      }
      size[lead] = static_cast<std::uint32_t>(acc.size());
    }
  });
  if (!merged.load()) return false;

  // New numbering in the order of the leaders, and each group's reference count.
  std::vector<std::uint32_t> index(n, kNone);
  std::vector<std::uint32_t> leaders;
  for (std::size_t c = 0; c < n; ++c) {
    if (leader[c] == c) {
      index[c] = static_cast<std::uint32_t>(leaders.size());
      leaders.push_back(static_cast<std::uint32_t>(c));
    }
  }
  const std::size_t groups = leaders.size();
  IrregularBuildCells out;
  out.boxes.resize(groups);
  out.begin.assign(groups + 1, 0u);
  for (std::size_t g = 0; g < groups; ++g) out.begin[g + 1] = out.begin[g] + size[leaders[g]];
  out.refs.resize(out.begin[groups]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups, 256), [&](const auto& r) {
    std::vector<std::uint32_t> acc, joined;
    for (std::size_t g = r.begin(); g != r.end(); ++g) {
      const std::uint32_t lead = leaders[g];
      auto box = cells.boxes[lead];
      auto refs = cells.refs_of(lead);
      std::uint32_t c = next[lead];
      if (c == kNone || leader[c] != lead) {  // a group of one: most of them
        out.boxes[g] = box;
        std::copy(refs.begin(), refs.end(), out.refs.begin() + out.begin[g]);
        continue;
      }
      acc.assign(refs.begin(), refs.end());
      for (; c != kNone && leader[c] == lead; c = next[c]) {
        box[axis + 3] = cells.boxes[c][axis + 3];
        unite(acc, cells.refs_of(c), joined);
        acc.swap(joined);
      }
      out.boxes[g] = box;
      std::copy(acc.begin(), acc.end(), out.refs.begin() + out.begin[g]);
    }
  });
  // The map's leaves now name the merged cells.
  auto renumber = [&](std::vector<std::uint32_t>& entries) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, entries.size(), 4096), [&](const auto& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        std::uint32_t& e = entries[i];
        if (e & IrregularGridData::kLeaf) e = index[leader[e & ~IrregularGridData::kLeaf]] | IrregularGridData::kLeaf;
      }
    });
  };
  renumber(data.top);
  renumber(data.map);
  cells = std::move(out);
  return true;
}

}  // namespace

void merge_cells(IrregularBuildCells& cells, IrregularGridData& data, const IrregularGridConfig& config) {
  for (int round = 0; round < config.merge_rounds; ++round) {
    bool any = false;
    for (int axis = 0; axis < 3; ++axis) any = merge_pass(cells, data, config, axis) || any;
    if (!any) break;
  }
}

}  // namespace raylab
