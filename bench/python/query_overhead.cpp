// raylab_query_overhead: what a batched closest-hit query (RayQuery::intersect, the call behind
// the Python module's Scene.intersect) costs beyond finding the hits, on the rays of a .rays file.
//
//     raylab_query_overhead SCENE RAYS [--threads T] [--repeats R] [--allow-outside-paths]
//
// Times two forms of the same query, interleaved, and prints the median Mrays/s of each as one
// JSON object on stdout:
//   hits_only    t and prim_id written, the other answers' pointers null: the hit and nothing
//                more, as `raylab bench` times it, but through the query's chunks;
//   all_outputs  t, prim_id, object_id, uv and normal, into arrays allocated once (the module
//                writes all five).
// bench/python/bench_python.py runs it beside `raylab bench` and the Python module on the same
// rays, so that a gap between the module and the C++ figures can be split into its causes.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "raylab/io/ray_file.h"
#include "raylab/io/scene_loader.h"
#include "raylab/query/ray_query.h"

namespace {

using raylab::HitArrays;
using raylab::Ray;
using raylab::RayBatch;

struct Args {
  std::string scene, rays;
  int threads = 1;
  int repeats = 5;
  bool allow_outside_paths = false;
};

// The arguments, or a message on stderr and exit 2.
Args parse(int argc, char** argv) {
  Args a;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--threads" || arg == "--repeats") && i + 1 < argc) {
      (arg == "--threads" ? a.threads : a.repeats) = std::atoi(argv[++i]);
    } else if (arg == "--allow-outside-paths") {
      a.allow_outside_paths = true;
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.size() != 2 || a.threads < 1 || a.repeats < 1) {
    std::fputs("usage: raylab_query_overhead SCENE RAYS [--threads T>=1] [--repeats R>=1] [--allow-outside-paths]\n",
               stderr);
    std::exit(2);
  }
  a.scene = positional[0];
  a.rays = positional[1];
  return a;
}

// The rays as the Python module passes them: origins and directions read in place from the
// records, with one tmin and tmax for all when every ray has the same (else each ray's own).
RayBatch batch_of(const std::vector<Ray>& rays, bool& per_ray_limits) {
  RayBatch b = RayBatch::of(rays);
  per_ray_limits = std::any_of(rays.begin(), rays.end(), [&](const Ray& r) {
    return r.tmin != rays.front().tmin || r.tmax != rays.front().tmax;
  });
  if (!per_ray_limits && !rays.empty()) {
    b.tmin = rays.front().tmin;
    b.tmax = rays.front().tmax;
    b.tmins = b.tmaxs = nullptr;
  }
  return b;
}

// The five answer arrays of `n` rays.
struct Answers {
  explicit Answers(std::size_t n) : t(n), uv(2 * n), normal(3 * n), prim(n), object(n) {}
  HitArrays all() { return {t.data(), prim.data(), object.data(), uv.data(), normal.data()}; }
  HitArrays hits_only() { return {t.data(), prim.data(), nullptr, nullptr, nullptr}; }
  std::vector<float> t, uv, normal;
  std::vector<std::int32_t> prim, object;
};

template <class Fn>
double seconds_of(const Fn& fn) {
  const auto start = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median_mrays(std::vector<double> seconds, std::size_t rays) {
  std::sort(seconds.begin(), seconds.end());
  const std::size_t n = seconds.size();
  const double s = n % 2 == 1 ? seconds[n / 2] : 0.5 * (seconds[n / 2 - 1] + seconds[n / 2]);
  return s > 0.0 ? static_cast<double>(rays) / s / 1e6 : 0.0;
}

int run(const Args& a) {
  raylab::LoadOptions load;
  load.allow_outside_paths = a.allow_outside_paths;
  const raylab::RayQuery query = [&] {
    raylab::RayQuery q = raylab::RayQuery::from_scene(raylab::load_scene(a.scene, load));
    q.build("bvh", {}, a.threads);
    return q;
  }();
  const std::vector<Ray> rays = raylab::read_rays(a.rays);
  bool per_ray_limits = false;
  const RayBatch batch = batch_of(rays, per_ray_limits);
  raylab::QueryOptions options;
  options.threads = a.threads;

  Answers answers(rays.size());
  query.intersect(batch, answers.all(), options);  // warm-up
  std::vector<double> hits_only, all_outputs;
  for (int r = 0; r < a.repeats; ++r) {
    hits_only.push_back(seconds_of([&] { query.intersect(batch, answers.hits_only(), options); }));
    all_outputs.push_back(seconds_of([&] { query.intersect(batch, answers.all(), options); }));
  }
  fmt::print(
      "{{\"rays\": {}, \"threads\": {}, \"repeats\": {}, \"per_ray_limits\": {}, "
      "\"mrays_per_s\": {{\"hits_only\": {:.4f}, \"all_outputs\": {:.4f}}}}}\n",
      rays.size(), a.threads, a.repeats, per_ray_limits ? "true" : "false", median_mrays(hits_only, rays.size()),
      median_mrays(all_outputs, rays.size()));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raylab_query_overhead: %s\n", e.what());
    return 1;
  }
}
