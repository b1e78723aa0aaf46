// `raylab quality`, the printing half: the bar ratios' line, the aligned table, the CSV and the
// JSON document of a QualityResult.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "raylab/lab/quality_study.h"
#include "report_json.h"

namespace raylab {
namespace {

using detail::ReportJson;

std::string psnr_text(double v) { return std::isfinite(v) ? fmt::format("{:.2f}", v) : "inf"; }

}  // namespace

std::string format_bar_ratios(const BarRatios& r) {
  return fmt::format(
      "{} (budget {}) vs {} at {} spp: primary rays x{:.3f}, RMSE x{:.3f}, p99.9 x{:.3f}, time x{:.3f}, time at "
      "equal RMSE x{:.3f}",
      r.sampler, r.budget, r.baseline, r.baseline_budget, r.rays, r.rmse, r.p999, r.time, r.time_at_equal_rmse);
}

std::string format_quality_table(const QualityResult& result, const std::string& scene_name) {
  std::size_t name_width = 8;
  for (const QualityRow& r : result.rows) name_width = std::max(name_width, r.sampler.size());
  const int nw = static_cast<int>(name_width) + 2;
  std::string out = fmt::format(
      "scene {}: {}x{}, filter {}{}, depth {}; up to {} seeds per row (center, regular, adaptive-corners: one)\n",
      scene_name, result.width, result.height, result.filter,
      result.filter_radius > 0.f ? fmt::format(" (radius {:g})", result.filter_radius) : "", result.max_depth,
      result.seeds);
  out += fmt::format("reference: {}\n", result.reference.empty() ? "(given)" : result.reference);
  out += "RMSE of linear RGB (mean and min..max over seeds); PSNR and SSIM on sRGB; p99.9: pixel error percentile;\n";
  out += "rays/px: primary rays per pixel (mean); time: median render time\n";
  out += fmt::format("{:<{}}{:>7}{:>6}{:>9}{:>10}{:>11}{:>23}{:>9}{:>8}{:>10}\n", "sampler", nw, "budget", "spp",
                     "rays/px", "time s", "RMSE", "RMSE min..max", "PSNR dB", "SSIM", "p99.9");
  for (const QualityRow& r : result.rows) {
    out += fmt::format("{:<{}}{:>7}{:>6}{:>9.2f}{:>10.4f}{:>11.5f}{:>23}{:>9}{:>8.4f}{:>10.5f}\n", r.sampler, nw,
                       r.budget, r.spp, r.rays_per_pixel, r.seconds, r.rmse,
                       fmt::format("{:.5f}..{:.5f}", r.rmse_min, r.rmse_max), psnr_text(r.psnr), r.ssim, r.p999);
  }
  return out;
}

std::string format_quality_csv(const QualityResult& result) {
  std::string out =
      "sampler,budget,spp,seeds,rays_per_pixel,seconds,rmse,rmse_min,rmse_max,rmse_stddev,psnr_db,ssim,p999\n";
  for (const QualityRow& r : result.rows) {
    out += fmt::format("{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{:.6g},{:.6g}\n", r.sampler, r.budget,
                       r.spp, r.seeds, r.rays_per_pixel, r.seconds, r.rmse, r.rmse_min, r.rmse_max, r.rmse_stddev,
                       std::isfinite(r.psnr) ? fmt::format("{:.6g}", r.psnr) : "inf", r.ssim, r.p999);
  }
  return out;
}

std::string format_quality_json(const QualityResult& result, const std::string& scene_name) {
  ReportJson doc = {{"scene", scene_name},
                    {"width", result.width},
                    {"height", result.height},
                    {"filter", result.filter},
                    {"filter_radius", result.filter_radius},
                    {"max_depth", result.max_depth},
                    {"seeds", result.seeds},
                    {"reference", result.reference}};
  ReportJson& rows = doc["rows"] = ReportJson::array();
  for (const QualityRow& r : result.rows) {
    rows.push_back({{"sampler", r.sampler},
                    {"budget", r.budget},
                    {"spp", r.spp},
                    {"seeds", r.seeds},
                    {"rays_per_pixel", r.rays_per_pixel},
                    {"seconds", r.seconds},
                    {"rmse", r.rmse},
                    {"rmse_min", r.rmse_min},
                    {"rmse_max", r.rmse_max},
                    {"rmse_stddev", r.rmse_stddev},
                    {"psnr_db", r.psnr},  // null where infinite (an exact match)
                    {"ssim", r.ssim},
                    {"p999", r.p999}});
  }
  if (const std::optional<BarRatios> b = bar_ratios(result)) {
    doc["bar"] = {{"sampler", b->sampler},
                  {"baseline", b->baseline},
                  {"budget", b->budget},
                  {"rays_ratio", b->rays},
                  {"rmse_ratio", b->rmse},
                  {"p999_ratio", b->p999},
                  {"time_ratio", b->time},
                  {"time_at_equal_rmse_ratio", b->time_at_equal_rmse},
                  {"baseline_budget", b->baseline_budget}};
  }
  return detail::report_text(doc);
}

}  // namespace raylab
