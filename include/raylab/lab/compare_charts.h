#pragma once
/// \file
/// The pictures of `raylab compare`: the bar chart of its figures and the per-pixel heat maps of
/// traversal work. They are drawn by io's generic SVG and PNG writers; the comparison's data is
/// lab's, so the glue lives here (io stays below lab).

#include <string>
#include <vector>

#include "raylab/lab/accel_compare.h"

namespace raylab {

/// The comparison as a chart: Mrays/s per structure and ray kind, then build time per
/// structure. Skipped structures keep their place with no bars and "(skipped)" in the label.
std::string compare_chart_svg(const CompareResult& result, const std::string& scene_name);

/// Writes compare_chart_svg to `path` atomically.
void write_compare_chart(const CompareResult& result, const std::string& scene_name, const std::string& path);

/// Writes the heat maps of a comparison into `dir` (created if missing): for each structure
/// that ran and counts its work, `<name>-tests.png` (primitive tests per primary ray) and
/// `<name>-nodes.png` (nodes or cells visited), each the size of the comparison's image, each
/// kind on one scale shared by all structures, each with its legend beside it
/// (`<name>-tests.legend.png`). Returns the paths written. Throws InputError when the folder
/// cannot be made.
std::vector<std::string> write_compare_heatmaps(const CompareResult& result, const std::string& dir);

}  // namespace raylab
