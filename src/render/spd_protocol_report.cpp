// The SPD protocol's counts as the command line prints them, and as JSON.

#include "raylab/render/spd_protocol_report.h"

#include <fmt/format.h>

#include <array>
#include <optional>

#include "json_text.h"
#include "raylab/render/spd_statistics.h"

namespace raylab {
namespace {

using detail::json_number;
using detail::json_string;

// One row of the table: a ray kind, what the README gives for it, and which of our figures that is.
struct KindRow {
  std::string_view label;
  std::uint64_t cast;
  std::uint64_t hit;
  std::string_view readme_column;  // the compare_with_published column it matches
};

std::array<KindRow, 4> kind_rows(const SpdProtocolCounts& c) {
  return {{{"eye", c.primary, c.primary_hits, "eye hits"},
           {"reflection", c.reflection, c.reflection_hits, "reflection"},
           {"refraction", c.refraction, c.refraction_hits, "refraction"},
           {"shadow", c.shadow, c.shadow_hits, "shadow"}}};
}

const SpdPublishedRow* published_row(const SpdPublishedTable& table, const SpdSource* source) {
  return source == nullptr ? nullptr : table.find(source->generator->name, source->size);
}

std::optional<SpdCountComparison> column(const std::vector<SpdCountComparison>& all, std::string_view name) {
  for (const SpdCountComparison& c : all) {
    if (c.column == name) return c;
  }
  return std::nullopt;
}

}  // namespace

std::string format_spd_protocol_table(const SpdProtocolCounts& counts, ShadowFacing facing, const SpdSource* source) {
  const SpdPublishedRow* readme = published_row(spd_readme_table(), source);
  const std::vector<SpdCountComparison> published =
      readme ? compare_with_published(counts, *readme) : std::vector<SpdCountComparison>{};
  std::string out = fmt::format(
      "SPD protocol: 512x512, eye rays through the 513x513 pixel corners, depth 5, shadow rays by the {} normal\n",
      spd_facing_name(facing));
  out += fmt::format("{:<14}{:>12}{:>12}", "rays", "cast", "hit");
  out += readme ? fmt::format("{:>14}{:>9}\n", "SPD README", "ratio") : "\n";
  for (const KindRow& row : kind_rows(counts)) {
    out += fmt::format("{:<14}{:>12}{:>12}", row.label, row.cast, row.hit);
    const std::optional<SpdCountComparison> c = column(published, row.readme_column);
    out += c ? fmt::format("{:>14}{:>9.4f}\n", c->published, c->ratio()) : "\n";
  }
  out += fmt::format("total internal reflections: {} (transmitter hits with a reflection ray, no refraction ray)\n",
                     counts.total_internal_reflections);
  if (readme) {
    out += fmt::format(
        "SPD README: {} at size {}; its figure is eye hits for eye rays, rays cast for the others "
        "(it expects tracers to agree within about 10%)\n",
        readme->scene, readme->size);
  }
  return out;
}

std::string format_spd_protocol_json(const SpdProtocolResult& result, std::string_view scene, ShadowFacing facing,
                                     const SpdSource* source) {
  std::string rays;
  for (const KindRow& row : kind_rows(result.counts)) {
    rays += fmt::format("{}{}: {{\"cast\": {}, \"hit\": {}}}", rays.empty() ? "" : ", ", json_string(row.label),
                        row.cast, row.hit);
  }
  std::string published;
  for (const SpdPublishedTable* table : {&spd_readme_table(), &havran_sixta_table()}) {
    const SpdPublishedRow* row = published_row(*table, source);
    if (row == nullptr) continue;
    std::string figures;
    for (const SpdCountComparison& c : compare_with_published(result.counts, *row)) {
      figures +=
          fmt::format("{}{{\"column\": {}, \"ours\": {}, \"published\": {}, \"ratio\": {}}}",
                      figures.empty() ? "" : ", ", json_string(c.column), c.ours, c.published, json_number(c.ratio()));
    }
    published += fmt::format("{}{{\"table\": {}, \"source\": {}, \"size\": {}, \"figures\": [{}]}}",
                             published.empty() ? "" : ", ", json_string(table->name), json_string(table->source),
                             row->size, figures);
  }
  return fmt::format(
      "{{\"scene\": {}, \"facing\": {}, \"width\": {}, \"height\": {}, \"max_depth\": 5, \"seconds\": {}, "
      "\"rays\": {{{}}}, \"total_internal_reflections\": {}, \"published\": [{}]}}\n",
      json_string(scene), json_string(spd_facing_name(facing)), kSpdProtocolSize, kSpdProtocolSize,
      json_number(result.seconds), rays, result.counts.total_internal_reflections, published);
}

}  // namespace raylab
