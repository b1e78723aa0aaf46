#pragma once
/// \file
/// Published ray counts of the SPD testing procedure, kept as data so that raylab's own counts
/// can be set beside numbers that other people's tracers produced.

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "raylab/render/spd_protocol.h"

namespace raylab {

/// One scene's row of a published table. A column the table does not give is empty.
struct SpdPublishedRow {
  std::string_view scene;                         ///< generator name ("balls", ...)
  int size = 0;                                   ///< the generator size whose scene the table counted
  std::optional<std::uint64_t> eye_hits{};        ///< eye rays that hit an object
  std::optional<std::uint64_t> reflection{};      ///< reflection rays cast
  std::optional<std::uint64_t> refraction{};      ///< refraction rays cast
  std::optional<std::uint64_t> secondary{};       ///< reflection plus refraction rays cast
  std::optional<std::uint64_t> secondary_hits{};  ///< of which hit an object
  std::optional<std::uint64_t> shadow{};          ///< shadow rays cast
  std::optional<std::uint64_t> shadow_hits{};     ///< shadow rays blocked by an object
};

/// A published table of ray counts for the seven SPD scenes (eye rays through the 513 x 513
/// pixel corners, ray trees 5 deep).
struct SpdPublishedTable {
  std::string_view name;                  ///< short name for reports
  std::string_view source;                ///< where it is published
  std::span<const SpdPublishedRow> rows;  ///< one per scene, in alphabetical order

  /// The row of `scene` when the table counted it at generator size `size`; null otherwise.
  const SpdPublishedRow* find(std::string_view scene, int size) const;
};

/// The statistics table of the SPD README (Readme.txt of SPD 3.14, Eric Haines): eye hit rays,
/// reflect rays, refract rays and shadow rays, at the sizes that give the primitive counts it
/// lists (teapot: size 12, 9,264 primitives). It says tracers should agree within about 10%.
const SpdPublishedTable& spd_readme_table();

/// Havran & Sixta's invariants (1999, "Comparison of hierarchical grids", shipped with the SPD
/// as havran_stats_grids.txt): eye hits, shadow rays and their hits, secondary rays and their
/// hits, from the GOLEM renderer.
const SpdPublishedTable& havran_sixta_table();

/// One published figure beside raylab's.
struct SpdCountComparison {
  std::string_view column;      ///< "eye hits", "reflection", "refraction", "secondary", ...
  std::uint64_t ours = 0;       ///< raylab's count
  std::uint64_t published = 0;  ///< the table's
  /// ours / published (1 when both are 0; infinity when only the table's is 0).
  double ratio() const;
};

/// Every figure `row` publishes, beside the matching count of `counts`, in the table's order.
std::vector<SpdCountComparison> compare_with_published(const SpdProtocolCounts& counts, const SpdPublishedRow& row);

}  // namespace raylab
