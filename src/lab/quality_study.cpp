// `raylab quality`, the measuring half: options, the renders of every sampler and budget, the
// error measures, the bar ratios. The table, CSV and JSON are in quality_format.cpp.

#include "raylab/lab/quality_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>

#include "median.h"
#include "raylab/core/error.h"
#include "raylab/core/hash64.h"
#include "raylab/lab/image_metrics.h"
#include "raylab/render/adaptive.h"
#include "raylab/render/renderer.h"
#include "raylab/sampling/pixel_sampler.h"

namespace raylab {
namespace {

using detail::median;

constexpr int kMaxBudget = 1 << 16;
constexpr int kMaxSeeds = 1000;

// The study takes every sampler a render does, except "auto" (which is one of them by another name).
bool is_study_sampler(std::string_view s) {
  const std::vector<std::string_view> names = render_sampler_names();
  return std::find(names.begin(), names.end(), s) != names.end();
}

std::string valid_samplers() {
  std::string out;
  for (std::string_view s : render_sampler_names()) out += (out.empty() ? "" : ", ") + std::string(s);
  return out;
}

// Splits "a,b,,c" at commas, trimming blanks; empty entries are kept so they can be reported.
std::vector<std::string> split_list(std::string_view text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    std::string_view item = text.substr(start, comma == std::string_view::npos ? text.npos : comma - start);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    out.emplace_back(item);
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

// The renders a study makes, in order, with the weight (samples per pixel) that progress uses.
struct PlannedRender {
  std::size_t row = 0;
  int seed = 0;
  double weight = 1.0;
};

}  // namespace

std::vector<std::string> quality_sampler_names() {
  const std::vector<std::string_view> names = render_sampler_names();
  return {names.begin(), names.end()};
}

bool sampler_is_deterministic(std::string_view s) { return s == "center" || s == "regular" || s == "adaptive-corners"; }

int used_spp(std::string_view sampler, int budget) {
  return is_adaptive_sampler(sampler) ? budget : valid_spp(sampler, budget);
}

void validate_quality_options(const QualityOptions& o) {
  if (o.samplers.empty()) throw UsageError("no sampler to study (valid: " + valid_samplers() + ")");
  for (std::size_t i = 0; i < o.samplers.size(); ++i) {
    const std::string& s = o.samplers[i];
    if (!is_study_sampler(s)) {
      throw UsageError("unknown sampler '" + s + "' (valid: " + valid_samplers() + ")");
    }
    if (std::find(o.samplers.begin(), o.samplers.begin() + static_cast<std::ptrdiff_t>(i), s) !=
        o.samplers.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw UsageError("sampler '" + s + "' is listed twice");
    }
  }
  if (o.budgets.empty()) throw UsageError("no sample budget to study (e.g. --budgets 1,4,16,64)");
  for (std::size_t i = 0; i < o.budgets.size(); ++i) {
    const int b = o.budgets[i];
    if (b < 1 || b > kMaxBudget) {
      throw UsageError(fmt::format("sample budget {} is out of range (1 to {})", b, kMaxBudget));
    }
    if (std::count(o.budgets.begin(), o.budgets.end(), b) > 1) {
      throw UsageError(fmt::format("sample budget {} is listed twice", b));
    }
  }
  if (o.seeds < 1 || o.seeds > kMaxSeeds) {
    throw UsageError(fmt::format("seed count {} is out of range (1 to {})", o.seeds, kMaxSeeds));
  }
  if (o.reference_spp < 1 || o.reference_spp > kMaxBudget) {
    throw UsageError(fmt::format("reference samples {} is out of range (1 to {})", o.reference_spp, kMaxBudget));
  }
}

std::vector<int> parse_budget_list(std::string_view text) {
  std::vector<int> out;
  for (const std::string& item : split_list(text)) {
    std::size_t used = 0;
    long value = -1;
    try {
      value = std::stol(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size() || value < 1 || value > kMaxBudget) {
      throw UsageError(fmt::format("--budgets: '{}' is not a sample count from 1 to {} (e.g. --budgets 1,4,16,64)",
                                   item, kMaxBudget));
    }
    out.push_back(static_cast<int>(value));
  }
  return out;
}

std::vector<std::string> parse_sampler_list(std::string_view text) {
  std::vector<std::string> out = split_list(text);
  for (const std::string& s : out) {
    if (!is_study_sampler(s)) {
      throw UsageError("--samplers: unknown sampler '" + s + "' (valid: " + valid_samplers() + ")");
    }
  }
  return out;
}

const QualityRow* QualityResult::find(std::string_view sampler, int budget) const {
  for (const QualityRow& r : rows) {
    if (r.sampler == sampler && r.budget == budget) return &r;
  }
  return nullptr;
}

RenderSettings reference_settings(const RenderSettings& scene_settings, const QualityOptions& options) {
  RenderSettings s = scene_settings;
  s.sampler = "jittered";
  s.spp = valid_spp("jittered", options.reference_spp);
  s.seed = options.reference_seed;
  return s;
}

Film render_reference(const Scene& scene, const Accelerator& accel, const QualityOptions& options,
                      const std::function<void(int, int)>& on_progress) {
  Scene work = scene;
  work.settings = reference_settings(scene.settings, options);
  Film film(work.settings.width, work.settings.height);
  RenderOptions ro;
  ro.threads = options.threads;
  ro.on_progress = on_progress;
  render(work, accel, film, ro);
  return film;
}

std::string reference_key_text(const RenderSettings& s, const QualityOptions& o) {
  const RenderSettings r = reference_settings(s, o);
  // Everything that changes the reference image and is not already in the scene source's key
  // (the command's overrides), spelled out so that the key can be read when debugging.
  return fmt::format(
      "raylab reference v{}\nsource {}\nsize {}x{}\nfilter {} radius {}\nmax_depth {}\nbackground {} {} {}\n"
      "sky_gradient {} horizon {} {} {}\nambient {} {} {}\nsampler {} spp {} seed {}\n",
      kReferenceFormatVersion, o.reference_key, r.width, r.height, r.filter, r.filter_radius, r.max_depth,
      r.background.x, r.background.y, r.background.z, r.sky_gradient ? 1 : 0, r.horizon.x, r.horizon.y, r.horizon.z,
      r.ambient.x, r.ambient.y, r.ambient.z, r.sampler, r.spp, r.seed);
}

std::string reference_file_name(const RenderSettings& s, const QualityOptions& o) {
  return fmt::format("reference-{:016x}.exr", Hash64::of(reference_key_text(s, o)));
}

QualityResult run_quality_study(const Scene& scene, const Accelerator& accel, const Film& reference,
                                const QualityOptions& options) {
  validate_quality_options(options);
  const RenderSettings& base = scene.settings;
  if (reference.width() != base.width || reference.height() != base.height) {
    throw InputError("", fmt::format("the reference image is {}x{} but the study renders {}x{}", reference.width(),
                                     reference.height(), base.width, base.height));
  }
  // What the renderer would refuse (an adaptive sampler with a filter other than the pixel
  // box, a bad filter) is refused now, not after the rows before it have run.
  for (const std::string& s : options.samplers) {
    RenderSettings probe = base;
    probe.sampler = s;
    check_sampling_settings(probe);
  }
  std::vector<int> budgets = options.budgets;
  std::sort(budgets.begin(), budgets.end());

  QualityResult result;
  result.width = base.width;
  result.height = base.height;
  result.filter = base.filter;
  result.filter_radius = base.filter_radius;
  result.max_depth = base.max_depth;
  result.seeds = options.seeds;
  result.threads = options.threads;

  // The plan first, so that progress knows the total work.
  std::vector<PlannedRender> plan;
  for (const std::string& sampler : options.samplers) {
    for (const int budget : budgets) {
      if (sampler == "center" && budget != budgets.front()) continue;  // one sample whatever the budget
      QualityRow row;
      row.sampler = sampler;
      row.budget = budget;
      row.spp = used_spp(sampler, budget);
      row.seeds = sampler_is_deterministic(sampler) ? 1 : options.seeds;
      for (int seed = 0; seed < row.seeds; ++seed) plan.push_back({result.rows.size(), seed, double(row.spp)});
      result.rows.push_back(row);
    }
  }
  double total = 0.0;
  for (const PlannedRender& p : plan) total += p.weight;

  Scene work = scene;
  Film film(base.width, base.height);
  const double pixels = static_cast<double>(base.width) * static_cast<double>(base.height);
  std::vector<std::vector<ImageError>> errors(result.rows.size());
  std::vector<std::vector<double>> seconds(result.rows.size()), rays(result.rows.size());
  double done = 0.0;
  for (const PlannedRender& p : plan) {
    QualityRow& row = result.rows[p.row];
    work.settings.sampler = row.sampler;
    work.settings.spp = row.budget;
    // An adaptive sampler's budget is the most samples a pixel may take: 4^depth.
    if (is_adaptive_sampler(row.sampler)) work.settings.aa_depth = adaptive_depth_for_spp(row.budget);
    work.settings.seed = static_cast<std::uint64_t>(p.seed);
    RenderOptions ro;
    ro.threads = options.threads;
    if (options.on_progress) {
      const std::string step = fmt::format("{} {} spp, seed {}", row.sampler, row.budget, p.seed);
      ro.on_progress = [&, step, weight = p.weight](int tiles_done, int tiles) {
        options.on_progress((done + weight * tiles_done / std::max(tiles, 1)) / total, step);
      };
    }
    const RenderResult r = render(work, accel, film, ro);
    done += p.weight;
    const std::uint64_t primary = r.primary_rays();
    rays[p.row].push_back(pixels > 0 ? static_cast<double>(primary) / pixels : 0.0);
    seconds[p.row].push_back(r.seconds);
    errors[p.row].push_back(measure_error(film, reference));
  }

  for (std::size_t i = 0; i < result.rows.size(); ++i) {
    QualityRow& row = result.rows[i];
    const std::vector<ImageError>& e = errors[i];
    const double n = static_cast<double>(e.size());
    row.rays_per_pixel = std::accumulate(rays[i].begin(), rays[i].end(), 0.0) / n;
    row.seconds = median(seconds[i]);
    row.rmse_min = std::numeric_limits<double>::infinity();
    row.rmse_max = 0.0;
    for (const ImageError& x : e) {
      row.rmse += x.rmse / n;
      row.psnr += x.psnr / n;
      row.ssim += x.ssim / n;
      row.p999 += x.p999 / n;
      row.rmse_min = std::min(row.rmse_min, x.rmse);
      row.rmse_max = std::max(row.rmse_max, x.rmse);
    }
    double var = 0.0;
    for (const ImageError& x : e) var += (x.rmse - row.rmse) * (x.rmse - row.rmse);
    row.rmse_stddev = e.size() > 1 ? std::sqrt(var / (n - 1.0)) : 0.0;
  }
  return result;
}

std::optional<BarRatios> bar_ratios(const QualityResult& result, std::string_view sampler, std::string_view baseline,
                                    int baseline_budget) {
  const QualityRow* b = result.find(baseline, baseline_budget);
  if (!b) return std::nullopt;
  std::vector<const QualityRow*> rows;
  for (const QualityRow& r : result.rows) {
    if (r.sampler == sampler) rows.push_back(&r);
  }
  if (rows.empty()) return std::nullopt;
  std::sort(rows.begin(), rows.end(),
            [](const QualityRow* x, const QualityRow* y) { return x->rays_per_pixel < y->rays_per_pixel; });
  // The cheapest row that errs no more by both measures, else by RMSE alone.
  const QualityRow* a = nullptr;
  for (const QualityRow* r : rows) {
    if (r->rmse <= b->rmse && r->p999 <= b->p999) {
      a = r;
      break;
    }
  }
  for (std::size_t i = 0; !a && i < rows.size(); ++i) {
    if (rows[i]->rmse <= b->rmse) a = rows[i];
  }
  if (!a) {
    a = *std::min_element(rows.begin(), rows.end(),
                          [](const QualityRow* x, const QualityRow* y) { return x->rmse < y->rmse; });
  }
  auto ratio = [](double x, double y) { return y > 0.0 ? x / y : (x > 0.0 ? INFINITY : 1.0); };
  BarRatios r;
  r.sampler = a->sampler;
  r.baseline = b->sampler;
  r.budget = a->budget;
  r.baseline_budget = b->budget;
  r.rays = ratio(a->rays_per_pixel, b->rays_per_pixel);
  r.rmse = ratio(a->rmse, b->rmse);
  r.p999 = ratio(a->p999, b->p999);
  r.time = ratio(a->seconds, b->seconds);
  // Time to reach the baseline's RMSE: walk the rows by time; interpolate in log-log between
  // the last row above the target and the first at or below it.
  std::sort(rows.begin(), rows.end(), [](const QualityRow* x, const QualityRow* y) { return x->seconds < y->seconds; });
  r.time_at_equal_rmse = NAN;
  const double target = b->rmse;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i]->rmse > target) continue;
    double t = rows[i]->seconds;
    if (i > 0) {
      const QualityRow& hi = *rows[i - 1];  // errs more, cheaper
      const QualityRow& lo = *rows[i];
      if (hi.rmse > 0.0 && lo.rmse > 0.0 && hi.seconds > 0.0 && lo.seconds > 0.0 && hi.rmse != lo.rmse) {
        const double f = (std::log(target) - std::log(hi.rmse)) / (std::log(lo.rmse) - std::log(hi.rmse));
        t = std::exp(std::log(hi.seconds) + f * (std::log(lo.seconds) - std::log(hi.seconds)));
      }
    }
    r.time_at_equal_rmse = ratio(t, b->seconds);
    break;
  }
  return r;
}

}  // namespace raylab
