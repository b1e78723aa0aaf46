// `raylab compare`, the measuring half: ray sets, timed builds and passes, counted passes, the
// agreement check. The table, CSV and JSON are in accel_compare_format.cpp.

#include "raylab/lab/accel_compare.h"
#include "raylab/core/thread_count.h"

#include <tbb/combinable.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <limits>
#include <span>
#include <string_view>

#include "median.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/core/stopwatch.h"

namespace raylab {
namespace {

using detail::median;

using Clock = SteadyClock;

// A structure that builds faster than this is built again (up to kMaxBuilds times) and the
// median reported: one build of a few milliseconds is mostly noise on a shared machine.
constexpr double kQuickBuildBudget = 0.5;
constexpr int kMaxBuilds = 5;
// The brute-force calibration grows its sample until it has run at least this long.
constexpr double kCalibrationSeconds = 0.02;
// Rays handed to one task at a time: enough to amortise scheduling, small enough to balance.
constexpr std::size_t kGrain = 512;

void progress(const CompareOptions& o, const std::string& line) {
  if (o.on_progress) o.on_progress(line);
}

template <class Body>
void for_each_ray(std::size_t n, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
  });
}

// One pass over the rays of `kind` through the uncounted (timed) entry points; the answers are
// stored, which also keeps the work from being optimised away. Returns the wall-clock seconds.
double trace_pass(const Accelerator& accel, const RaySets& sets, BenchRayKind kind, RayAnswers& answers) {
  const std::vector<Ray>& rays = sets[kind].rays;
  const auto start = Clock::now();
  if (kind == BenchRayKind::kShadow) {
    answers.shadow.resize(rays.size());
    for_each_ray(rays.size(), [&](std::size_t i) { answers.shadow[i] = accel.occluded(rays[i]) ? 1 : 0; });
  } else {
    std::vector<Hit>& hits = kind == BenchRayKind::kPrimary ? answers.primary : answers.diffuse;
    hits.assign(rays.size(), Hit{});
    for_each_ray(rays.size(), [&](std::size_t i) {
      Ray ray = rays[i];
      accel.intersect(ray, hits[i]);
    });
  }
  return seconds_since(start);
}

std::uint32_t saturate(std::uint64_t v) {
  return static_cast<std::uint32_t>(std::min<std::uint64_t>(v, std::numeric_limits<std::uint32_t>::max()));
}

// The counted pass of `kind`: averages per ray, and per-pixel counts for primary rays.
void count_pass(const Accelerator& accel, const RaySets& sets, BenchRayKind kind, AccelMeasure& m) {
  const std::vector<Ray>& rays = sets[kind].rays;
  const bool primary = kind == BenchRayKind::kPrimary;
  if (primary) {
    m.pixel_tests.assign(rays.size(), 0);
    m.pixel_nodes.assign(rays.size(), 0);
  }
  tbb::combinable<TraversalStats> total;
  for_each_ray(rays.size(), [&](std::size_t i) {
    TraversalStats s;
    if (kind == BenchRayKind::kShadow) {
      accel.occluded_counted(rays[i], s);
    } else {
      Ray ray = rays[i];
      Hit hit;
      accel.intersect_counted(ray, hit, s);
    }
    if (primary) {
      m.pixel_tests[i] = saturate(s.prim_tests);
      m.pixel_nodes[i] = saturate(s.nodes_visited);
    }
    total.local() += s;
  });
  const TraversalStats sum = total.combine([](TraversalStats a, const TraversalStats& b) { return a += b; });
  KindMeasure& k = m.kinds[static_cast<int>(kind)];
  const double n = static_cast<double>(std::max<std::size_t>(rays.size(), 1));
  k.nodes_per_ray = static_cast<double>(sum.nodes_visited) / n;
  k.tests_per_ray = static_cast<double>(sum.prim_tests) / n;
}

// Estimated seconds that brute force would spend on the comparison (`passes` passes over every
// ray on `threads` threads): primitives x rays x the cost of one primitive test, the cost
// measured on one thread over an evenly spread sample that grows until it takes measurable time.
double estimate_brute_seconds(const Accelerator& brute, const RaySets& sets, int threads, int passes) {
  const std::size_t total = sets.total_rays();
  if (total == 0) return 0.0;
  const double prims = static_cast<double>(std::max<std::size_t>(brute.info().primitive_count, 1));
  std::size_t stride = std::max<std::size_t>(total / 16, 1);
  for (;;) {
    std::size_t sampled = 0;
    const auto start = Clock::now();
    for (int k = 0; k < kBenchRayKinds; ++k) {
      const auto kind = static_cast<BenchRayKind>(k);
      const std::vector<Ray>& rays = sets[kind].rays;
      for (std::size_t i = 0; i < rays.size(); i += stride, ++sampled) {
        if (kind == BenchRayKind::kShadow) {
          (void)brute.occluded(rays[i]);
        } else {
          Ray ray = rays[i];
          Hit hit;
          (void)brute.intersect(ray, hit);
        }
      }
    }
    const double elapsed = seconds_since(start);
    if (sampled > 0 && (elapsed >= kCalibrationSeconds || stride == 1)) {
      const double per_test = elapsed / (static_cast<double>(sampled) * prims);
      return per_test * prims * static_cast<double>(total) * passes / std::max(threads, 1);
    }
    stride = std::max<std::size_t>(stride / 4, 1);
  }
}

// Builds `name` once or, while builds are quick, up to kMaxBuilds times; keeps the last one.
std::unique_ptr<Accelerator> timed_build(const AccelBuilder& build, const std::string& name, AccelMeasure& m) {
  std::vector<double> times;
  double total = 0.0;
  std::unique_ptr<Accelerator> accel;
  do {
    accel.reset();  // never two copies in memory at once
    const auto start = Clock::now();
    accel = build(name);
    times.push_back(seconds_since(start));
    total += times.back();
  } while (static_cast<int>(times.size()) < kMaxBuilds && total < kQuickBuildBudget);
  m.build_seconds = median(times);
  m.builds = static_cast<int>(times.size());
  return accel;
}

void check_names(const std::vector<std::string>& names) {
  if (names.empty()) throw UsageError("no acceleration structure to compare (valid: " + accelerator_name_list() + ")");
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i), names[i]) !=
        names.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw UsageError("acceleration structure '" + names[i] + "' is listed twice");
    }
  }
}

// Measures one structure; fills `answers` with its answers to every ray.
void measure(const Accelerator& accel, const RaySets& sets, const CompareOptions& options, AccelMeasure& m,
             RayAnswers& answers) {
  for (int k = 0; k < kBenchRayKinds; ++k) {
    const auto kind = static_cast<BenchRayKind>(k);
    KindMeasure& km = m.kinds[k];
    km.rays = sets[kind].rays.size();
    progress(options, m.name + ": tracing " + std::to_string(km.rays) + " " + bench_ray_kind_name(kind) + " rays");
    std::vector<double> times;
    for (int r = 0; r < options.repeat; ++r) times.push_back(trace_pass(accel, sets, kind, answers));
    const double seconds = median(times);
    km.mrays_per_second = seconds > 0.0 ? static_cast<double>(km.rays) / seconds * 1e-6 : 0.0;
    if (kind == BenchRayKind::kShadow) {
      km.hits = static_cast<std::size_t>(std::count(answers.shadow.begin(), answers.shadow.end(), 1));
    } else {
      const std::vector<Hit>& hits = kind == BenchRayKind::kPrimary ? answers.primary : answers.diffuse;
      km.hits =
          static_cast<std::size_t>(std::count_if(hits.begin(), hits.end(), [](const Hit& h) { return h.valid(); }));
    }
    if (m.has_counts) count_pass(accel, sets, kind, m);
  }
}

CompareResult run_comparison(const Scene& scene, const CompareOptions& options, const AccelBuilder& build) {
  check_names(options.accels);
  if (options.repeat < 1) throw UsageError("the repeat count must be at least 1");
  CompareResult result;
  result.primitive_count = scene.primitive_count();
  result.repeat = options.repeat;
  result.width = options.rays.width;
  result.height = options.rays.height;
  result.threads = tbb::this_task_arena::max_concurrency();

  progress(options, "ray sets: building " + options.ray_source + " for the primary hits");
  RaySets sets;
  {
    const std::unique_ptr<Accelerator> source = build(options.ray_source);
    sets = make_ray_sets(scene, *source, options.rays);
  }
  for (int k = 0; k < kBenchRayKinds; ++k) result.rays[k] = sets.sets[k].rays.size();

  // Brute force goes first: it is the reference unless the estimate rules it out. Otherwise
  // the first structure listed is.
  std::vector<std::size_t> order(options.accels.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_partition(order.begin(), order.end(), [&](std::size_t i) { return options.accels[i] == "brute"; });

  result.accels.resize(options.accels.size());
  RayAnswers reference;
  bool have_reference = false;
  for (std::size_t i : order) {
    AccelMeasure& m = result.accels[i];
    m.name = options.accels[i];
    m.has_counts = m.name != "embree";
    progress(options, m.name + ": building");
    std::unique_ptr<Accelerator> accel = timed_build(build, m.name, m);
    m.info = accel->info();
    m.bytes_per_primitive = static_cast<double>(m.info.memory_bytes) /
                            static_cast<double>(std::max<std::uint64_t>(result.primitive_count, 1));
    if (m.name == "brute") {
      progress(options, "brute: estimating its time");
      m.estimated_seconds = estimate_brute_seconds(*accel, sets, result.threads, options.repeat + 1);
      if (m.estimated_seconds > options.brute_limit_seconds) {
        m.skipped = true;
        continue;
      }
    }
    RayAnswers answers;
    measure(*accel, sets, options, m, answers);
    if (!have_reference) {
      m.is_reference = true;
      result.reference = m.name;
      reference = std::move(answers);
      have_reference = true;
    } else {
      m.mismatch_count =
          find_mismatches(sets, reference, answers, options.t_tolerance, options.mismatches_kept, m.mismatches);
    }
  }
  return result;
}

}  // namespace

bool CompareResult::agreed() const {
  return std::all_of(accels.begin(), accels.end(), [](const AccelMeasure& m) { return m.mismatch_count == 0; });
}

std::vector<std::string> default_compare_accels() {
  std::vector<std::string> names = {"brute", "grid", "grid2", "octree", "irregular", "bvh"};
  for (std::string_view n : accelerator_names()) {
    if (n == "embree") names.emplace_back(n);
  }
  return names;
}

CompareResult compare_accelerators(const Scene& scene, const CompareOptions& options) {
  const std::span<const std::string_view> valid = accelerator_names();
  for (const std::string& name : options.accels) {
    if (std::find(valid.begin(), valid.end(), name) == valid.end()) {
      throw UsageError("unknown acceleration structure '" + name + "' (valid: " + accelerator_name_list() + ")");
    }
  }
  const AccelBuilder build = [&](const std::string& name) {
    SceneAccelOptions o = options.structure;
    o.top = name;
    return make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, o);
  };
  return compare_accelerators(scene, options, build);
}

CompareResult compare_accelerators(const Scene& scene, const CompareOptions& options, const AccelBuilder& build) {
  const int threads = usable_threads(options.threads);
  tbb::task_arena arena(threads);
  CompareResult result;
  arena.execute([&] { result = run_comparison(scene, options, build); });
  return result;
}

RayAnswers trace_answers(const Accelerator& accel, const RaySets& sets) {
  RayAnswers answers;
  for (int k = 0; k < kBenchRayKinds; ++k) trace_pass(accel, sets, static_cast<BenchRayKind>(k), answers);
  return answers;
}

std::size_t find_mismatches(const RaySets& sets, const RayAnswers& expected, const RayAnswers& found, float tolerance,
                            std::size_t keep, std::vector<Mismatch>& out) {
  std::size_t count = 0;
  auto record = [&](Mismatch m) {
    ++count;
    if (out.size() < keep) out.push_back(m);
  };
  for (BenchRayKind kind : {BenchRayKind::kPrimary, BenchRayKind::kShadow, BenchRayKind::kDiffuse}) {
    const std::vector<Ray>& rays = sets[kind].rays;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      Mismatch m;
      m.kind = kind;
      m.index = i;
      m.ray = rays[i];
      if (kind == BenchRayKind::kShadow) {
        m.expected_occluded = expected.shadow.at(i) != 0;
        m.found_occluded = found.shadow.at(i) != 0;
        if (m.expected_occluded != m.found_occluded) record(m);
      } else {
        const bool primary = kind == BenchRayKind::kPrimary;
        m.expected = (primary ? expected.primary : expected.diffuse).at(i);
        m.found = (primary ? found.primary : found.diffuse).at(i);
        if (match_hits(m.expected, m.found, tolerance, origin_slack(m.ray)) == HitMatch::kDifferent) record(m);
      }
    }
  }
  return count;
}

}  // namespace raylab
