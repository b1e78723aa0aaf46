#pragma once
/// \file
/// `raylab quality`: every pixel sampler at several sample budgets, rendered with several seeds
/// and measured against one reference image — error against cost, side by side.
///
/// This part renders and measures; reading, caching and writing the reference image is in
/// lab/quality_reference.h, the chart in lab/quality_chart.h.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/render/film.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Every sampler a study can run: the uniform ones (center, regular, random, jittered, cmj,
/// sobol) and the adaptive ones (adaptive-corners, adaptive), in that order.
std::vector<std::string> quality_sampler_names();

/// True for the samplers whose sample positions do not depend on the seed (center, regular,
/// adaptive-corners): a study runs them with one seed only. (Area-light samples still follow the
/// seed; one seed measures them fairly enough, and the others' spread shows their variance.)
bool sampler_is_deterministic(std::string_view sampler);

/// The sample count a sampler really uses for `budget`: valid_spp for the uniform samplers
/// (center 1, regular and jittered a square, sobol a power of two), the budget itself (the most
/// per pixel) for the adaptive ones.
int used_spp(std::string_view sampler, int budget);

/// The seed of the reference render: far from the study's seeds 0, 1, ..., so that the
/// reference's noise is independent of every measured image.
constexpr std::uint64_t kReferenceSeed = 0x5265666572656e63ull;  // "Referenc"

/// Bumped whenever the reference rendering changes (renderer, key layout), so that references
/// cached by an older raylab are not reused. 2: fitted mesh cameras stand on the detected up axis,
/// and an image of another shape than the scene's widens the view instead of cropping it.
constexpr int kReferenceFormatVersion = 2;

/// Progress of a study: the fraction of the work done (weighted by samples per pixel, so a
/// 64-spp render counts 64 times a 1-spp one), and what is rendering now ("jittered 16 spp,
/// seed 3"). Called from worker threads as tiles finish: it must be thread-safe.
using QualityProgress = std::function<void(double fraction, const std::string& step)>;

/// How a study runs. Defaults are the command's.
struct QualityOptions {
  std::vector<std::string> samplers = quality_sampler_names();  ///< in table order
  std::vector<int> budgets = {1, 4, 16, 64};                    ///< samples per pixel asked for (adaptive: the most)
  int seeds = 5;  ///< renders per row with seeds 0 .. seeds-1 (deterministic samplers: one)
  /// "auto" (render the reference, cached) or the path of an EXR or PFM image.
  std::string reference = "auto";
  /// Samples per pixel of an auto reference: jittered (a square: 1024 is 32 x 32) with the
  /// scene's filter.
  int reference_spp = 1024;
  std::uint64_t reference_seed = kReferenceSeed;  ///< seed of an auto reference
  /// Folder of cached auto references; empty: render every time, cache nothing.
  std::string cache_dir;
  /// Identifies the scene source in the cache key (the command: the scene as named plus a hash
  /// of the file's bytes when it is a file; see scene_source_key in lab/quality_reference.h).
  std::string reference_key;
  int threads = 0;              ///< worker threads; 0 = all cores
  QualityProgress on_progress;  ///< may be empty
};

/// Throws UsageError naming the bad value (and the valid ones where there is a list) when a
/// sampler is unknown or listed twice, the lists are empty, a budget is outside 1 .. 65536 or
/// listed twice, seeds is outside 1 .. 1000, or reference_spp is outside 1 .. 65536.
void validate_quality_options(const QualityOptions& options);

/// Parses a comma-separated budget list ("1,4,16,64"); throws UsageError naming the bad entry.
std::vector<int> parse_budget_list(std::string_view text);

/// Parses a comma-separated sampler list ("jittered,adaptive"); throws UsageError naming an
/// unknown entry and listing the valid ones.
std::vector<std::string> parse_sampler_list(std::string_view text);

/// One line of the study: one sampler at one budget, over its seeds.
struct QualityRow {
  std::string sampler;
  int budget = 0;               ///< samples per pixel asked for
  int spp = 0;                  ///< used_spp(sampler, budget)
  int seeds = 0;                ///< renders measured
  double rays_per_pixel = 0.0;  ///< primary rays per pixel, mean over the seeds
  double seconds = 0.0;         ///< render time, median over the seeds
  double rmse = 0.0;            ///< linear RGB RMSE against the reference, mean over the seeds
  double rmse_min = 0.0;        ///< smallest RMSE of a seed
  double rmse_max = 0.0;        ///< largest RMSE of a seed
  double rmse_stddev = 0.0;     ///< standard deviation of the seeds' RMSE (0 for one seed)
  double psnr = 0.0;            ///< dB, mean over the seeds (infinite if one seed matched exactly)
  double ssim = 0.0;            ///< mean over the seeds
  double p999 = 0.0;            ///< 99.9th percentile of the pixel error, mean over the seeds
};

/// A whole study.
struct QualityResult {
  int width = 0;  ///< image size
  int height = 0;
  std::string filter;         ///< reconstruction filter of every render
  float filter_radius = 0.f;  ///< as set (0 = the filter's default)
  int max_depth = 0;
  int seeds = 0;                 ///< seeds asked for
  int threads = 0;               ///< as asked (0 = all cores)
  std::string reference;         ///< how the reference was made, for the report (set by the caller)
  std::vector<QualityRow> rows;  ///< samplers in the order asked, budgets ascending

  /// The row of `sampler` at `budget`, or null.
  const QualityRow* find(std::string_view sampler, int budget) const;
};

/// The settings of an auto reference render: the scene's, with the jittered sampler at
/// valid_spp("jittered", options.reference_spp) samples and options.reference_seed.
RenderSettings reference_settings(const RenderSettings& scene_settings, const QualityOptions& options);

/// Renders the auto reference (reference_settings) of `scene` with `accel` built over it.
/// `on_progress` gets (tiles done, tiles total) and may be empty.
Film render_reference(const Scene& scene, const Accelerator& accel, const QualityOptions& options,
                      const std::function<void(int, int)>& on_progress = {});

/// The text the reference cache key hashes: the format version, options.reference_key, the
/// image size, filter and radius, max depth, background, reference spp and seed.
std::string reference_key_text(const RenderSettings& scene_settings, const QualityOptions& options);

/// The cache file name of an auto reference: "reference-" + 16 hex digits of Hash64::of
/// reference_key_text + ".exr".
std::string reference_file_name(const RenderSettings& scene_settings, const QualityOptions& options);

/// Runs the study on `scene` (its settings give the size, filter, depth and adaptive
/// parameters; sampler, spp and seed are set per render) against `reference`. For each sampler
/// and budget (budgets ascending; center at the smallest budget only, since it has one sample)
/// it renders with seeds 0 .. seeds-1 (deterministic samplers: seed 0 only) and measures each
/// image with measure_error. The renders use a copy of the scene. Throws UsageError for bad
/// options (validate_quality_options) or an adaptive sampler with a filter other than the pixel
/// box (the renderer refuses it; this says so before any work), and InputError naming both
/// sizes when the reference is not the scene's image size.
QualityResult run_quality_study(const Scene& scene, const Accelerator& accel, const Film& reference,
                                const QualityOptions& options);

/// A sampler against a baseline row, as ratios sampler / baseline: below 1 means the sampler
/// traces fewer rays, errs less or runs faster.
struct BarRatios {
  std::string sampler;
  std::string baseline;
  int budget = 0;           ///< the sampler row compared (see bar_ratios)
  int baseline_budget = 0;  ///< the baseline row's budget
  double rays = 0.0;        ///< primary rays per pixel
  double rmse = 0.0;
  double p999 = 0.0;
  double time = 0.0;  ///< render time (a ratio within one run: machines are shared and noisy)
  /// Time the sampler needs to reach the baseline's RMSE, over the baseline's time: interpolated
  /// log-log between the two budgets of the sampler whose RMSE brackets the baseline's; the
  /// cheapest row's time when every row errs less (an upper bound); NaN when none errs as little.
  double time_at_equal_rmse = 0.0;
};

/// `sampler` against `baseline` at `baseline_budget`: of the sampler's rows (any budget), the
/// one tracing the fewest rays among those whose RMSE and 99.9th percentile are both no higher
/// than the baseline's, else among those whose RMSE is no higher, else the one with the lowest
/// RMSE. Nothing when the baseline row or every sampler row is missing.
std::optional<BarRatios> bar_ratios(const QualityResult& result, std::string_view sampler = "adaptive",
                                    std::string_view baseline = "jittered", int baseline_budget = 16);

/// One line: "adaptive (budget 64) vs jittered at 16 spp: primary rays x0.410, RMSE x0.930, p99.9 x0.880,
/// time x0.520, time at equal RMSE x0.450".
std::string format_bar_ratios(const BarRatios& ratios);

/// The table, aligned, one row per sampler and budget, with a header saying what was measured.
std::string format_quality_table(const QualityResult& result, const std::string& scene_name);

/// The table as CSV: a header line, then a line per row (PSNR "inf" where infinite).
std::string format_quality_csv(const QualityResult& result);

/// The study as a JSON document (an infinite PSNR is written as null), with the bar ratios of
/// adaptive against jittered at 16 when both rows exist.
std::string format_quality_json(const QualityResult& result, const std::string& scene_name);

}  // namespace raylab
