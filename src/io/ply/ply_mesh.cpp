#include "ply_mesh.h"

#include "raylab/core/error.h"

namespace raylab::ply_detail {

Slot slot_named(std::string_view name) {
  if (name == "x") return kX;
  if (name == "y") return kY;
  if (name == "z") return kZ;
  if (name == "nx") return kNx;
  if (name == "ny") return kNy;
  if (name == "nz") return kNz;
  if (name == "u" || name == "s" || name == "texture_u" || name == "texture_s") return kU;
  if (name == "v" || name == "t" || name == "texture_v" || name == "texture_t") return kV;
  return kSkip;
}

VertexLayout vertex_layout(const Element& e, const std::string& file) {
  VertexLayout layout;
  std::array<bool, kSlots> seen{};
  for (const Property& p : e.properties) {
    const Slot slot = slot_named(p.name);
    if (slot != kSkip && p.list) {
      throw InputError(file, p.line, p.col, "vertex property " + quoted(p.name) + " must be a scalar, not a list");
    }
    if (slot != kSkip) seen[slot] = true;
    layout.slots.push_back(slot);
  }
  if (!seen[kX] || !seen[kY] || !seen[kZ]) {
    throw InputError(file, e.line, e.col, "element 'vertex' needs properties x, y and z");
  }
  layout.normals = seen[kNx] && seen[kNy] && seen[kNz];
  layout.uvs = seen[kU] && seen[kV];
  for (Slot& slot : layout.slots) {
    if ((!layout.normals && slot >= kNx && slot <= kNz) || (!layout.uvs && (slot == kU || slot == kV))) slot = kSkip;
  }
  return layout;
}

std::size_t index_property(const Element& e, const std::string& file) {
  for (std::size_t i = 0; i < e.properties.size(); ++i) {
    const Property& p = e.properties[i];
    if (p.name != "vertex_indices" && p.name != "vertex_index") continue;
    if (!p.list) throw InputError(file, p.line, p.col, quoted(p.name) + " must be a list");
    if (!is_integer(p.type)) throw InputError(file, p.line, p.col, quoted(p.name) + " must list integers");
    return i;
  }
  throw InputError(file, e.line, e.col, "element " + quoted(e.name) + " has no 'vertex_indices' list");
}

std::string out_of_range(std::int64_t index, std::size_t vertex_count) {
  return "vertex index " + std::to_string(index) + " is out of range (the file has " + std::to_string(vertex_count) +
         " vertices)";
}

}  // namespace raylab::ply_detail
