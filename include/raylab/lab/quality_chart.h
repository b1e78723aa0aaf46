#pragma once
/// \file
/// The chart of `raylab quality`: error against cost, drawn by io's log-log line chart.

#include <string>

#include "raylab/io/line_chart.h"
#include "raylab/lab/quality_study.h"

namespace raylab {

/// The study as a chart: RMSE against primary rays per pixel, one line per sampler through its
/// budgets; the title names the scene and the image size.
LineChart quality_chart(const QualityResult& result, const std::string& scene_name);

/// Writes the SVG of quality_chart to `path` atomically.
void write_quality_chart(const QualityResult& result, const std::string& scene_name, const std::string& path);

}  // namespace raylab
