// The chart of `raylab quality`: one line per sampler through its budgets.

#include "raylab/lab/quality_chart.h"

#include <fmt/format.h>

#include <algorithm>

namespace raylab {

LineChart quality_chart(const QualityResult& result, const std::string& scene_name) {
  LineChart chart;
  chart.title =
      fmt::format("raylab quality: {} ({}x{}, filter {})", scene_name, result.width, result.height, result.filter);
  chart.x_label = "primary rays per pixel";
  chart.y_label = "RMSE against the reference (linear RGB)";
  for (const QualityRow& r : result.rows) {
    auto it = std::find_if(chart.series.begin(), chart.series.end(),
                           [&](const LineSeries& s) { return s.name == r.sampler; });
    if (it == chart.series.end()) it = chart.series.insert(chart.series.end(), LineSeries{r.sampler, {}});
    it->points.push_back({r.rays_per_pixel, r.rmse});
  }
  for (LineSeries& s : chart.series) {
    std::sort(s.points.begin(), s.points.end(), [](const ChartPoint& a, const ChartPoint& b) { return a.x < b.x; });
  }
  return chart;
}

void write_quality_chart(const QualityResult& result, const std::string& scene_name, const std::string& path) {
  write_line_chart(quality_chart(result, scene_name), path);
}

}  // namespace raylab
