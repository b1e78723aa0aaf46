#pragma once
/// \file
/// `raylab compare`: every acceleration structure on the same rays of one scene — build time,
/// memory, throughput, traversal work — and the proof that they all see the same world.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/two_level.h"
#include "raylab/lab/hit_agreement.h"
#include "raylab/lab/ray_sets.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// How a comparison runs.
struct CompareOptions {
  /// Structures in table order (factory names; see default_compare_accels()).
  std::vector<std::string> accels;
  /// Wrapping, bottom level and parameters of every structure; `top` is set to each name in turn.
  SceneAccelOptions structure;
  /// Image size and seed of the ray sets.
  RaySetOptions rays;
  /// The structure whose primary hits spawn the shadow and diffuse rays (built untimed).
  std::string ray_source = "bvh";
  int threads = 0;                    ///< worker threads; 0 = all cores
  int repeat = 3;                     ///< timed passes per ray kind; the median is reported
  double brute_limit_seconds = 60.0;  ///< brute force is skipped when estimated slower than this
  float t_tolerance =
      static_cast<float>(kHitDistanceTolerance);        ///< relative distance within which two different hits agree
  std::size_t mismatches_kept = 5;                      ///< disagreeing rays kept per structure (all are counted)
  std::function<void(const std::string&)> on_progress;  ///< one line per step, for a log
};

/// One structure's numbers for one kind of ray.
struct KindMeasure {
  std::size_t rays = 0;           ///< rays traced
  std::size_t hits = 0;           ///< of which hit (closest hit) or were occluded (shadow)
  double mrays_per_second = 0.0;  ///< median over the timed passes
  double nodes_per_ray = 0.0;     ///< nodes or cells visited, from the counted pass
  double tests_per_ray = 0.0;     ///< ray-primitive tests, from the counted pass
};

/// A ray on which a structure and the reference disagree.
struct Mismatch {
  BenchRayKind kind = BenchRayKind::kPrimary;
  std::size_t index = 0;           ///< position in its ray set
  Ray ray;                         ///< as traced (tmax not yet shrunk)
  Hit expected;                    ///< the reference's closest hit (primary, diffuse)
  Hit found;                       ///< the structure's closest hit (primary, diffuse)
  bool expected_occluded = false;  ///< shadow rays: the reference's answer
  bool found_occluded = false;     ///< shadow rays: the structure's answer
};

/// Everything measured for one structure.
struct AccelMeasure {
  std::string name;
  bool skipped = false;              ///< brute force estimated above the limit: nothing else is set
  double estimated_seconds = 0.0;    ///< brute force: the estimate (also when it ran)
  double build_seconds = 0.0;        ///< median wall-clock time of `builds` builds
  int builds = 0;                    ///< builds timed (more when one build is quick)
  AccelInfo info;                    ///< as the structure reports it
  double bytes_per_primitive = 0.0;  ///< info.memory_bytes over the scene's primitive count
  KindMeasure kinds[kBenchRayKinds];
  bool has_counts = true;                  ///< false for Embree, which counts nothing
  std::vector<std::uint32_t> pixel_tests;  ///< primary rays: primitive tests per pixel (row-major)
  std::vector<std::uint32_t> pixel_nodes;  ///< primary rays: nodes or cells visited per pixel
  bool is_reference = false;               ///< the others were checked against this one
  std::size_t mismatch_count = 0;          ///< rays that disagree with the reference
  std::vector<Mismatch> mismatches;        ///< the first few of them
};

/// A whole comparison.
struct CompareResult {
  std::uint64_t primitive_count = 0;  ///< the scene's, instances included
  int width = 0;                      ///< image size of the primary rays
  int height = 0;
  std::size_t rays[kBenchRayKinds] = {};  ///< rays per kind
  int threads = 0;                        ///< threads that traced
  int repeat = 0;                         ///< timed passes per kind
  std::string reference;                  ///< structure the others were checked against ("" if none)
  std::vector<AccelMeasure> accels;       ///< in the order asked for

  /// True when no structure disagrees with the reference.
  bool agreed() const;
};

/// Builds the structure called `name` for the scene; the comparison times this call.
using AccelBuilder = std::function<std::unique_ptr<Accelerator>(const std::string& name)>;

/// The structures compared when none are named: brute, grid, octree, bvh, and embree when built in.
std::vector<std::string> default_compare_accels();

/// Runs the comparison with make_scene_accelerator. Each structure is built (several times
/// when quick; the median is kept), then for each ray kind traced `repeat` times in parallel
/// (median Mrays/s), then once more with counting. Brute force is calibrated on a sample of
/// the rays first and skipped when the estimate exceeds the limit. Agreement is checked against
/// brute force when it runs, else against the first structure. Throws UsageError for an
/// unknown or repeated name, an empty list or a repeat count below 1.
CompareResult compare_accelerators(const Scene& scene, const CompareOptions& options);

/// The same with structures made by `build` (names are not checked against the factory).
CompareResult compare_accelerators(const Scene& scene, const CompareOptions& options, const AccelBuilder& build);

/// A structure's answers to the ray sets.
struct RayAnswers {
  std::vector<Hit> primary;          ///< closest hits
  std::vector<std::uint8_t> shadow;  ///< 1 when occluded
  std::vector<Hit> diffuse;          ///< closest hits
};

/// Traces every ray of `sets` through `accel` (in parallel) and keeps the answers.
RayAnswers trace_answers(const Accelerator& accel, const RaySets& sets);

/// Compares `found` with `expected` ray by ray by the lab's one rule (match_hits, with the ray's
/// origin_slack; shadow rays by their occlusion); returns how many rays disagree and appends
/// the first `keep` of them to `out`.
std::size_t find_mismatches(const RaySets& sets, const RayAnswers& expected, const RayAnswers& found, float tolerance,
                            std::size_t keep, std::vector<Mismatch>& out);

/// The table, aligned, one row per structure, with a header saying what was measured.
std::string format_compare_table(const CompareResult& result, const std::string& scene_name);

/// Every disagreement kept, with its ray and both answers; empty when all agree.
std::string format_mismatches(const CompareResult& result);

/// The table as CSV (one header line, one line per structure; empty fields where skipped or n/a).
std::string format_compare_csv(const CompareResult& result);

/// The table as a JSON document.
std::string format_compare_json(const CompareResult& result, const std::string& scene_name);

}  // namespace raylab
