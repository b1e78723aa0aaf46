// The quality study's chart: a line per sampler through its budgets, in ray order, written as
// io's line chart draws it.

#include "raylab/lab/quality_chart.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace raylab {
namespace {

TEST(LineChart, QualityChartHasALinePerSamplerInRayOrder) {
  QualityResult r;
  r.width = 64;
  r.height = 48;
  r.filter = "box";
  auto row = [](std::string s, int budget, double rays, double rmse) {
    QualityRow q;
    q.sampler = std::move(s);
    q.budget = budget;
    q.rays_per_pixel = rays;
    q.rmse = rmse;
    return q;
  };
  r.rows = {row("center", 1, 1, 0.2), row("jittered", 4, 4, 0.05), row("jittered", 1, 1, 0.1),
            row("adaptive", 4, 1.7, 0.04), row("adaptive", 16, 2.5, 0.02)};
  const LineChart c = quality_chart(r, "aa-edges");
  ASSERT_EQ(c.series.size(), 3u);
  EXPECT_EQ(c.series[0].name, "center");
  EXPECT_EQ(c.series[1].name, "jittered");
  ASSERT_EQ(c.series[1].points.size(), 2u);
  EXPECT_EQ(c.series[1].points[0].x, 1.0);  // sorted by rays
  EXPECT_EQ(c.series[1].points[1].y, 0.05);
  EXPECT_EQ(c.series[2].points[1].x, 2.5);
  EXPECT_NE(c.title.find("aa-edges"), std::string::npos);
  EXPECT_NE(c.x_label.find("primary rays per pixel"), std::string::npos);

  const std::string path =
      (std::filesystem::temp_directory_path() / ("raylab-line-chart-" + std::to_string(::getpid()) + ".svg")).string();
  write_quality_chart(r, "aa-edges", path);
  std::ifstream in(path);
  const std::string written{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::filesystem::remove(path);
  EXPECT_EQ(written, line_chart_svg(c));
}

}  // namespace
}  // namespace raylab
