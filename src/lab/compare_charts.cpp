// The pictures of `raylab compare`: its figures as a bar chart, its per-pixel counts as heat maps.

#include "raylab/lab/compare_charts.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <span>
#include <system_error>

#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/heatmap.h"
#include "raylab/io/svg_chart.h"

namespace raylab {

std::string compare_chart_svg(const CompareResult& result, const std::string& scene_name) {
  BarPanel speed{"Throughput", "Mrays/s", {}, {}, {}};
  BarPanel build{"Build time", "milliseconds", {}, {"build"}, {}};
  BarPanel memory{"Memory", "bytes per primitive", {}, {"memory"}, {}};
  for (int k = 0; k < kBenchRayKinds; ++k) speed.series.emplace_back(bench_ray_kind_name(static_cast<BenchRayKind>(k)));
  for (const AccelMeasure& m : result.accels) {
    const std::string label = m.skipped ? m.name + " (skipped)" : m.name;
    std::vector<double> rates;
    for (const KindMeasure& k : m.kinds) rates.push_back(m.skipped || k.rays == 0 ? NAN : k.mrays_per_second);
    for (BarPanel* p : {&speed, &build, &memory}) p->groups.push_back(label);
    speed.values.push_back(rates);
    build.values.push_back({m.skipped ? NAN : m.build_seconds * 1e3});
    memory.values.push_back({m.skipped ? NAN : m.bytes_per_primitive});
  }
  const std::array<BarPanel, 3> panels = {speed, build, memory};
  return bar_chart_svg(fmt::format("raylab compare: {} ({} primitives, {}x{})", scene_name, result.primitive_count,
                                   result.width, result.height),
                       panels);
}

void write_compare_chart(const CompareResult& result, const std::string& scene_name, const std::string& path) {
  const std::string svg = compare_chart_svg(result, scene_name);
  write_file_atomically(path, std::span(reinterpret_cast<const unsigned char*>(svg.data()), svg.size()));
}

std::vector<std::string> write_compare_heatmaps(const CompareResult& result, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw InputError(dir, "cannot create the heat map folder: " + (ec ? ec.message() : "a file has that name"));
  }
  HeatScale tests, nodes;
  tests.max_value = nodes.max_value = 0.0;
  for (const AccelMeasure& m : result.accels) {
    for (std::uint32_t v : m.pixel_tests) tests.max_value = std::max(tests.max_value, static_cast<double>(v));
    for (std::uint32_t v : m.pixel_nodes) nodes.max_value = std::max(nodes.max_value, static_cast<double>(v));
  }
  std::vector<std::string> written;
  for (const AccelMeasure& m : result.accels) {
    if (m.skipped || !m.has_counts || m.pixel_tests.empty()) continue;
    const std::string base = (std::filesystem::path(dir) / m.name).string();
    auto write = [&](std::span<const std::uint32_t> values, const HeatScale& scale, const std::string& what,
                     const std::string& suffix) {
      const std::vector<std::string> paths = write_heatmap_png(
          values, result.width, result.height, scale, m.name + ": " + what + " per pixel, log scale", base + suffix);
      written.insert(written.end(), paths.begin(), paths.end());
    };
    write(m.pixel_tests, tests, "primitive tests", "-tests.png");
    write(m.pixel_nodes, nodes, "nodes or cells", "-nodes.png");
  }
  return written;
}

}  // namespace raylab
