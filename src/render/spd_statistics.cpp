// The published SPD statistics as data, and raylab's counts set beside them.

#include "raylab/render/spd_statistics.h"

#include <array>
#include <limits>

namespace raylab {
namespace {

SpdPublishedRow readme_row(std::string_view scene, int size, std::uint64_t eye_hits, std::uint64_t reflection,
                           std::uint64_t refraction, std::uint64_t shadow) {
  return {.scene = scene,
          .size = size,
          .eye_hits = eye_hits,
          .reflection = reflection,
          .refraction = refraction,
          .shadow = shadow};
}

SpdPublishedRow havran_row(std::string_view scene, int size, std::uint64_t eye_hits, std::uint64_t shadow,
                           std::uint64_t shadow_hits, std::uint64_t secondary, std::uint64_t secondary_hits) {
  return {.scene = scene,
          .size = size,
          .eye_hits = eye_hits,
          .secondary = secondary,
          .secondary_hits = secondary_hits,
          .shadow = shadow,
          .shadow_hits = shadow_hits};
}

// Readme.txt, "eye hit rays" to "shadow rays". The sizes are those whose scenes have the
// table's "total prim." (balls 7,382, gears 9,345, mount 8,196, rings 8,401, teapot 9,264 =
// 9,120 patches + 144 squares, tetra 4,096, tree 8,191).
const std::array<SpdPublishedRow, 7> kReadmeRows{
    readme_row("balls", 4, 263169, 175095, 0, 954368),        //
    readme_row("gears", 4, 245086, 304643, 207564, 2246955),  //
    readme_row("mount", 6, 173125, 354769, 354769, 412922),   //
    readme_row("rings", 7, 263169, 315236, 0, 1085002),       //
    readme_row("teapot", 12, 161120, 225248, 0, 407656),      //
    readme_row("tetra", 6, 49788, 0, 0, 46112),               //
    readme_row("tree", 11, 169836, 0, 0, 1097419),            //
};

// havran_stats_grids.txt, "Invariants". Its teapot's 161,546 eye hits are those of size 12.
const std::array<SpdPublishedRow, 7> kHavranRows{
    havran_row("balls", 4, 263169, 959244, 285178, 179884, 134368),    //
    havran_row("gears", 4, 245332, 2088012, 1057557, 494338, 365338),  //
    havran_row("mount", 6, 173685, 361037, 74555, 710436, 472351),     //
    havran_row("rings", 7, 263169, 1077336, 510719, 312879, 175688),   //
    havran_row("teapot", 12, 161546, 406340, 34757, 226235, 67688),    //
    havran_row("tetra", 6, 49950, 46262, 5538, 0, 0),                  //
    havran_row("tree", 11, 169907, 1110323, 47506, 0, 0),              //
};

}  // namespace

const SpdPublishedRow* SpdPublishedTable::find(std::string_view scene, int size) const {
  for (const SpdPublishedRow& row : rows) {
    if (row.scene == scene && row.size == size) return &row;
  }
  return nullptr;
}

const SpdPublishedTable& spd_readme_table() {
  static const SpdPublishedTable table{"SPD README", "Readme.txt of SPD 3.14 (Eric Haines), statistics table",
                                       kReadmeRows};
  return table;
}

const SpdPublishedTable& havran_sixta_table() {
  static const SpdPublishedTable table{
      "Havran & Sixta", "Havran and Sixta, Comparison of hierarchical grids, RTNews 12(1), 1999", kHavranRows};
  return table;
}

double SpdCountComparison::ratio() const {
  if (published == 0) return ours == 0 ? 1.0 : std::numeric_limits<double>::infinity();
  return static_cast<double>(ours) / static_cast<double>(published);
}

std::vector<SpdCountComparison> compare_with_published(const SpdProtocolCounts& counts, const SpdPublishedRow& row) {
  std::vector<SpdCountComparison> out;
  const auto add = [&](std::string_view column, std::uint64_t ours, const std::optional<std::uint64_t>& published) {
    if (published) out.push_back({column, ours, *published});
  };
  add("eye hits", counts.primary_hits, row.eye_hits);
  add("reflection", counts.reflection, row.reflection);
  add("refraction", counts.refraction, row.refraction);
  add("secondary", counts.secondary(), row.secondary);
  add("secondary hits", counts.secondary_hits(), row.secondary_hits);
  add("shadow", counts.shadow, row.shadow);
  add("shadow hits", counts.shadow_hits, row.shadow_hits);
  return out;
}

}  // namespace raylab
