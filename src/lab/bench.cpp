// `raylab bench`, the measuring half: builds, ray sets, agreement, interleaved timings. The
// table and JSON are in bench_format.cpp.

#include "raylab/lab/bench.h"
#include "raylab/core/isa.h"
#include "raylab/core/thread_count.h"

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <thread>
#include <utility>

#include "median.h"
#include "raylab/accel/bvh.h"
#include "raylab/accel/embree_reference.h"
#include "raylab/accel/wide_bvh.h"
#include "raylab/core/error.h"
#include "raylab/core/stopwatch.h"
#include "raylab/lab/hit_agreement.h"

namespace raylab {
namespace {

constexpr double kRelTol = kHitDistanceTolerance;  // relative tolerance on t between the two tracers
constexpr std::size_t kChunk = 1024;               // rays per work item of the timed loops: a multiple of 16
constexpr std::size_t kPacket = 16;
constexpr std::size_t kKeep = 5;  // disagreements described per set

enum class Way { kSingle, kPacket };

// Calls fn(begin, end) over chunks of [0, n) on `threads` threads (the caller is one of them),
// handed out dynamically because hit and miss regions cost very different amounts. Plain threads,
// not tasks: the timed loop is then the tracer and nothing else.
template <class Fn>
void parallel_chunks(std::size_t n, int threads, const Fn& fn) {
  if (threads <= 1 || n <= kChunk) return fn(std::size_t{0}, n);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t b; (b = next.fetch_add(kChunk, std::memory_order_relaxed)) < n;) fn(b, std::min(n, b + kChunk));
  };
  std::vector<std::jthread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
}

template <class Fn>
double seconds_of(const Fn& fn) {
  const auto start = SteadyClock::now();
  fn();
  return seconds_since(start);
}

// Closest hits by our structure, one ray or one packet of 16 at a time.
void trace(const Accelerator& a, std::span<const Ray> rays, std::span<Hit> hits, Way way, int threads) {
  parallel_chunks(rays.size(), threads, [&](std::size_t b, std::size_t e) {
    if (way == Way::kSingle) {
      for (std::size_t i = b; i < e; ++i) {
        Ray r = rays[i];  // intersect shrinks tmax: trace a copy
        hits[i] = Hit{};
        a.intersect(r, hits[i]);
      }
      return;
    }
    for (std::size_t p = b; p < e; p += kPacket) {
      const std::size_t n = std::min(kPacket, e - p);
      Ray r[kPacket];
      std::copy_n(rays.begin() + static_cast<std::ptrdiff_t>(p), n, r);
      std::fill_n(hits.begin() + static_cast<std::ptrdiff_t>(p), n, Hit{});
      a.intersect(std::span<Ray>(r, n), hits.subspan(p, n));
    }
  });
}

// Any hit by our structure.
void trace(const Accelerator& a, std::span<const Ray> rays, std::span<std::uint8_t> occluded, Way way, int threads) {
  parallel_chunks(rays.size(), threads, [&](std::size_t b, std::size_t e) {
    if (way == Way::kSingle) {
      for (std::size_t i = b; i < e; ++i) occluded[i] = a.occluded(rays[i]) ? 1 : 0;
      return;
    }
    for (std::size_t p = b; p < e; p += kPacket) {
      const std::size_t n = std::min(kPacket, e - p);
      a.occluded(rays.subspan(p, n), occluded.subspan(p, n));
    }
  });
}

// Closest hits by Embree (rtcIntersect1 or rtcIntersect16).
void trace(const EmbreeReference& ref, std::span<const Ray> rays, std::span<Hit> hits, Way way, int threads) {
  parallel_chunks(rays.size(), threads, [&](std::size_t b, std::size_t e) {
    if (way == Way::kSingle) return ref.intersect1(rays.subspan(b, e - b), hits.subspan(b, e - b));
    ref.intersect16(rays.subspan(b, e - b), hits.subspan(b, e - b));
  });
}

// Any hit by Embree (rtcOccluded1 or rtcOccluded16).
void trace(const EmbreeReference& ref, std::span<const Ray> rays, std::span<std::uint8_t> occluded, Way way,
           int threads) {
  parallel_chunks(rays.size(), threads, [&](std::size_t b, std::size_t e) {
    if (way == Way::kSingle) return ref.occluded1(rays.subspan(b, e - b), occluded.subspan(b, e - b));
    ref.occluded16(rays.subspan(b, e - b), occluded.subspan(b, e - b));
  });
}

// Distances agree by the lab's rule: within the relative tolerance, or within the rounding of
// positions near the ray's origin (hit_agreement.h says why).
bool close(double a, double b, const Ray& ray) { return distances_agree(a, b, kRelTol, origin_slack(ray)); }

// Distance along `ray` to primitive `prim` by our own test, ignoring tmax; for a triangle whose
// watertight test rejects the point (an edge its neighbour owns), the distance to its plane;
// NaN when there is no such primitive or no hit.
double t_of(const Geometry& g, const Ray& ray, std::uint32_t prim) {
  if (prim >= g.size()) return std::numeric_limits<double>::quiet_NaN();
  Ray r = ray;
  r.tmax = std::numeric_limits<float>::infinity();
  Hit h;
  if (g.intersect(prim, WatertightRay(r), r, h)) return h.t;
  if (prim >= g.triangles.size()) return std::numeric_limits<double>::quiet_NaN();
  const Triangle& tri = g.triangles[prim];
  const Vec3 n = triangle_normal(tri);
  return static_cast<double>(dot(tri.p0 - ray.origin, n)) / static_cast<double>(dot(ray.direction, n));
}

std::string ray_text(std::size_t i, const Ray& r) {
  return fmt::format("ray {}: origin ({}, {}, {}) direction ({}, {}, {}) t [{}, {})", i, r.origin.x, r.origin.y,
                     r.origin.z, r.direction.x, r.direction.y, r.direction.z, r.tmin, r.tmax);
}

std::string hit_text(const Hit& h) {
  return h.valid() ? fmt::format("t {} prim {}", h.t, h.prim_id) : std::string("miss");
}

// Our closest hits against the other side's, ray by ray, by the lab's rule (match_hits). A tie
// (different primitives at the same t) counts when the other side's primitive, tested by our own
// shape test, lies at that t too (shared edges, coplanar faces). A different t or hit/miss is an Embree edge crack when
// Embree's robust scene answers as we do; anything else is a disagreement. `robust` may be null (no Embree).
BenchAgreement check_closest(const Geometry& g, std::span<const Ray> rays, std::span<const Hit> ours,
                             std::span<const Hit> other, EmbreeReference* robust, const char* other_name) {
  BenchAgreement a;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Hit &o = ours[i], &e = other[i];
    const double slack = origin_slack(rays[i]);
    const HitMatch match = match_hits(o, e, kRelTol, slack);
    if (match == HitMatch::kSame) {
      ++a.same;
      continue;
    }
    if (match == HitMatch::kTie) {
      if (close(o.t, t_of(g, rays[i], e.prim_id), rays[i])) {
        ++a.ties;
        continue;
      }
    } else if (robust) {
      robust->build_robust();
      Hit r;
      robust->intersect1(rays.subspan(i, 1), std::span(&r, 1), true);
      if (match_hits(o, r, kRelTol, slack) != HitMatch::kDifferent) {
        ++a.embree_cracks;
        continue;
      }
    }
    if (++a.disagreements <= kKeep) {
      a.first.push_back(ray_text(i, rays[i]) + ": ours " + hit_text(o) + ", " + other_name + " " + hit_text(e));
    }
  }
  return a;
}

// Our any-hit answers against the other side's. A difference is an Embree edge crack when the
// robust scene answers as we do, and a tie when the nearest surface on the ray (by either side)
// lies within the tolerance of the ray's ends, where either answer is right.
BenchAgreement check_any(const Accelerator& ours_accel, std::span<const Ray> rays, std::span<const std::uint8_t> ours,
                         std::span<const std::uint8_t> other, EmbreeReference* robust, const char* other_name) {
  BenchAgreement a;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (ours[i] == other[i]) {
      ++a.same;
      continue;
    }
    Ray open = rays[i];
    open.tmax = std::numeric_limits<float>::infinity();
    Hit nearest[2];
    Ray copy = open;
    ours_accel.intersect(copy, nearest[0]);
    if (robust) {
      robust->build_robust();
      std::uint8_t r = 0;
      robust->occluded1(rays.subspan(i, 1), std::span(&r, 1), true);
      if (r == ours[i]) {
        ++a.embree_cracks;
        continue;
      }
      robust->intersect1(std::span(&open, 1), std::span(&nearest[1], 1), true);
    }
    auto at_end = [&](const Hit& h) {
      return h.valid() && (close(h.t, rays[i].tmax, rays[i]) || close(h.t, rays[i].tmin, rays[i]));
    };
    if (at_end(nearest[0]) || at_end(nearest[1])) {
      ++a.ties;
      continue;
    }
    if (++a.disagreements <= kKeep) {
      a.first.push_back(ray_text(i, rays[i]) + ": ours " + (ours[i] ? "occluded" : "clear") + ", " + other_name + " " +
                        (other[i] ? "occluded" : "clear"));
    }
  }
  return a;
}

// Median seconds of `repeats` runs of `ours` and, when given, `embree`, alternating: interleaving
// spreads clock, thermal and neighbour-load drift over both sides. `before_embree` runs before
// each Embree run, outside the clock.
template <class A, class B, class R>
std::pair<double, double> time_interleaved(int repeats, bool with_embree, const A& ours, const B& embree,
                                           const R& before_embree) {
  std::vector<double> a, b;
  for (int r = 0; r < repeats; ++r) {
    a.push_back(seconds_of(ours));
    if (!with_embree) continue;
    before_embree();
    b.push_back(seconds_of(embree));
  }
  return {detail::median(a), detail::median(b)};
}

double mrays(std::size_t n, double seconds) { return seconds > 0.0 ? static_cast<double>(n) / seconds / 1e6 : 0.0; }

// One set of rays to trace: what it is and how.
struct SetSpec {
  std::string name;
  std::span<const Ray> rays;
  bool closest = true;
  bool packets = false;
};

void check_options(const BenchOptions& o) {
  if (o.repeats < 1) throw UsageError("--repeats must be at least 1, not " + std::to_string(o.repeats));
  if (o.threads < 0) throw UsageError("--threads must not be negative, not " + std::to_string(o.threads));
  if (!o.use_file_rays && o.kinds.empty()) throw UsageError("no ray kinds to trace");
  if (!o.use_file_rays && (o.width < 1 || o.height < 1)) {
    throw UsageError("the image must be at least 1x1, not " + std::to_string(o.width) + "x" + std::to_string(o.height));
  }
}

// Everything one set needs across verification and timing.
class SetRun {
 public:
  SetRun(const SetSpec& spec, const Accelerator& ours, EmbreeReference* ref, int threads)
      : m_spec(spec), m_ours(ours), m_ref(ref), m_threads(threads) {
    const std::size_t n = spec.rays.size();
    if (spec.closest) {
      m_hits[0].resize(n), m_hits[1].resize(n), m_hits[2].resize(n), m_hits[3].resize(n);
    } else {
      m_flags[0].resize(n), m_flags[1].resize(n), m_flags[2].resize(n), m_flags[3].resize(n);
    }
  }

  // Traces every way once (untimed: also the warm-up) and checks the answers.
  BenchSetReport verify(const Geometry& g) {
    BenchSetReport s;
    s.name = m_spec.name;
    s.closest = m_spec.closest;
    s.packets = m_spec.packets;
    s.rays = m_spec.rays.size();
    run(0, Way::kSingle);
    if (m_spec.packets) run(1, Way::kPacket);
    if (m_ref) {
      run(2, Way::kSingle);
      if (m_spec.packets) run(3, Way::kPacket);
    }
    // Without Embree our packets are checked against our single rays.
    const int single_other = m_ref ? 2 : 0, packet_other = m_ref ? 3 : 0;
    const char* other = m_ref ? "embree" : "our single rays";
    if (m_spec.closest) {
      for (const Hit& h : m_hits[0]) s.answered += h.valid() ? 1 : 0;
      if (m_ref) s.single = check_closest(g, m_spec.rays, m_hits[0], m_hits[single_other], m_ref, other);
      if (m_spec.packets) s.packet = check_closest(g, m_spec.rays, m_hits[1], m_hits[packet_other], m_ref, other);
    } else {
      for (std::uint8_t f : m_flags[0]) s.answered += f;
      if (m_ref) s.single = check_any(m_ours, m_spec.rays, m_flags[0], m_flags[single_other], m_ref, other);
      if (m_spec.packets) s.packet = check_any(m_ours, m_spec.rays, m_flags[1], m_flags[packet_other], m_ref, other);
    }
    return s;
  }

  // Median Mrays/s of both sides, interleaved. Embree traces records (single or packets of 16)
  // prepared before the clock, as ours are from a prepared array of Ray (docs/performance.md:
  // filling each record just before its call costs Embree up to 1.7x); the records it consumed
  // are restored outside the clock, and its answers checked afterwards.
  BenchFigure time(Way way, int repeats) {
    const int slot = way == Way::kSingle ? 0 : 1;
    const bool packets = way == Way::kPacket;
    if (m_ref) m_ref->prepare(m_spec.rays, packets);
    const std::size_t n = m_spec.rays.size();
    const auto [ours, embree] = time_interleaved(
        repeats, m_ref != nullptr, [&] { run(slot, way); },
        [&] {
          // kChunk is a multiple of 16: each chunk starts a packet.
          parallel_chunks(n, m_threads, [&](std::size_t b, std::size_t e) {
            if (m_spec.closest) return packets ? m_ref->intersect16_prepared(b, e) : m_ref->intersect1_prepared(b, e);
            packets ? m_ref->occluded16_prepared(b, e) : m_ref->occluded1_prepared(b, e);
          });
        },
        [&] { m_ref->reset_prepared(0, n); });
    if (m_ref) check_prepared_answers(slot + 2);
    return {mrays(n, ours), m_ref ? mrays(n, embree) : 0.0};
  }

  // Our closest hits from the single-ray pass, or for any-hit rays a closest-hit pass now.
  std::vector<Hit> closest_hits() {
    if (m_spec.closest) return m_hits[0];
    std::vector<Hit> hits(m_spec.rays.size());
    trace(m_ours, m_spec.rays, std::span(hits), Way::kSingle, m_threads);
    return hits;
  }

 private:
  // Slots: 0 ours single, 1 ours packets, 2 Embree single, 3 Embree packets.
  // The prepared records must give what the same way gave in verify() (answers in `slot`): the
  // same records on the same scene, so any difference is a fault of the timing path.
  void check_prepared_answers(int slot) const {
    const std::size_t n = m_spec.rays.size();
    std::size_t differ = 0;
    if (m_spec.closest) {
      std::vector<Hit> hits(n);
      m_ref->prepared_hits(hits);
      for (std::size_t i = 0; i < n; ++i) {
        const Hit &a = hits[i], &b = m_hits[slot][i];
        differ +=
            a.prim_id != b.prim_id || std::bit_cast<std::uint32_t>(a.t) != std::bit_cast<std::uint32_t>(b.t) ? 1 : 0;
      }
    } else {
      std::vector<std::uint8_t> flags(n);
      m_ref->prepared_occluded(flags);
      for (std::size_t i = 0; i < n; ++i) differ += flags[i] != m_flags[slot][i] ? 1 : 0;
    }
    if (differ != 0) {
      throw std::logic_error("bench: Embree's prepared records answered " + std::to_string(differ) + " of the " +
                             m_spec.name + " rays otherwise than when verified");
    }
  }

  void run(int slot, Way way) {
    const bool embree = slot >= 2;
    if (m_spec.closest) {
      const std::span<Hit> out(m_hits[slot]);
      embree ? trace(*m_ref, m_spec.rays, out, way, m_threads) : trace(m_ours, m_spec.rays, out, way, m_threads);
    } else {
      const std::span<std::uint8_t> out(m_flags[slot]);
      embree ? trace(*m_ref, m_spec.rays, out, way, m_threads) : trace(m_ours, m_spec.rays, out, way, m_threads);
    }
  }

  const SetSpec& m_spec;
  const Accelerator& m_ours;
  EmbreeReference* m_ref;
  int m_threads;
  std::vector<Hit> m_hits[4];
  std::vector<std::uint8_t> m_flags[4];
};

// The exception message: counts per set and way, then the first rays.
std::string disagreement_message(const BenchReport& r) {
  std::string counts, rays;
  std::size_t total = 0;
  for (const BenchSetReport& s : r.sets) {
    for (const auto& [way, a] : {std::pair{"single", &s.single}, std::pair{"packet", &s.packet}}) {
      if (a->disagreements == 0) continue;
      total += a->disagreements;
      counts +=
          fmt::format("{}{} {} rays: {} of {}", counts.empty() ? "" : "; ", s.name, way, a->disagreements, s.rays);
      for (const std::string& line : a->first) rays += "\n  " + std::string(s.name) + " " + way + " " + line;
    }
  }
  return fmt::format("{} and {} disagree on {} rays ({}); the first:{}", r.accel,
                     r.embree ? "Embree" : "its own single rays", total, counts, rays);
}

}  // namespace

BenchReport run_bench(const Scene& scene, const BenchOptions& o) {
  return run_bench(scene, o, [&](const Geometry& g) { return make_accelerator(o.accel, g, o.accel_config); });
}

BenchReport run_bench(const Scene& scene, const BenchOptions& o, const BenchAccelBuilder& build) {
  check_options(o);
  const int threads = usable_threads(o.threads);
  // One cap for everything parallel: our builder, Embree's TBB tasks, the ray-set generation.
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  auto progress = [&](const std::string& line) {
    if (o.on_progress) o.on_progress(line);
  };
  const Geometry& g = scene.geometry;
  BenchReport rep;
  rep.accel = o.accel;
  rep.primitives = g.size();
  rep.triangles = g.triangles.size();
  rep.width = o.use_file_rays ? 0 : o.width;
  rep.height = o.use_file_rays ? 0 : o.height;
  rep.threads = threads;
  rep.repeats = o.repeats;

  rep.kernels = isa_name(active_isa());
  std::unique_ptr<EmbreeReference> ref;
  if (!o.against_embree) {
    rep.notes.push_back("Embree not measured (--against none): our figures only");
  } else if (!embree_reference_available()) {
    rep.notes.push_back("Embree not measured: raylab was built without Embree 3; our figures only");
  } else {
    progress("embree: creating the device and the first scene");
    ref = std::make_unique<EmbreeReference>(g, o.embree_isa);
    rep.embree = true;
    rep.user_primitives = ref->user_primitive_count();
    rep.notes.push_back(
        "Embree 3: default scene flags, RTC_BUILD_QUALITY_MEDIUM; single rays rtcIntersect1/rtcOccluded1, packets "
        "rtcIntersect16/rtcOccluded16 with a coherent context; edge disagreements settled by a robust scene; "
        "kernels: " +
        (o.embree_isa.empty() ? std::string("Embree's choice for this CPU") : o.embree_isa));
    if (rep.user_primitives > 0) {
      rep.notes.push_back(fmt::format(
          "{} non-triangle primitives are Embree user geometry calling raylab's own shape tests (not tessellated)",
          rep.user_primitives));
    }
  }

  // Builds, alternating like the traces; the last of ours is kept for tracing.
  progress(fmt::format("build: {} x {} and Embree", o.repeats, o.accel));
  std::unique_ptr<Accelerator> ours;
  std::vector<double> build_ours, build_embree;
  for (int r = 0; r < o.repeats; ++r) {
    ours.reset();  // free the previous build first, so neither side builds in the other's garbage
    build_ours.push_back(seconds_of([&] { ours = build(g); }));
    if (ref) build_embree.push_back(ref->rebuild());
  }
  const double prims = static_cast<double>(rep.primitives);
  const double ours_build = detail::median(build_ours), embree_build = detail::median(build_embree);
  rep.build_ms = {ours_build * 1e3, ref ? embree_build * 1e3 : 0.0};
  rep.build_mprims = {mrays(rep.primitives, ours_build), ref ? mrays(rep.primitives, embree_build) : 0.0};
  if (prims > 0) {
    rep.bytes_per_triangle = {static_cast<double>(ours->info().memory_bytes) / prims,
                              ref ? static_cast<double>(ref->scene_bytes()) / prims : 0.0};
  }
  progress("sah: pricing both binary trees");
  // Both binary trees priced as the wide BVH builds its own: leaves per block of four primitives
  // (Embree's leaves are blocks of four triangles too).
  const BvhConfig priced = WideBvh<simd::kNativeBoxWidth>::build_config(o.accel_config.bvh);
  rep.sah_cost.ours = rep.primitives > 0 ? sah_cost(build_bvh(g, priced), priced) : 0.0;
  if (ref) rep.sah_cost.embree = ref->binary_sah_cost(priced);

  // The ray sets.
  RaySets sets;
  std::vector<SetSpec> specs;
  if (o.use_file_rays) {
    specs.push_back({"file", o.file_rays, true, true});
    rep.notes.push_back(fmt::format("rays: {} rays of {}, closest hit, singles and packets of 16 consecutive rays",
                                    o.file_rays.size(), o.file_rays_name));
  } else {
    rep.light = bench_light(scene, rep.light_from_scene);
    const Vec3 p = rep.light.position;
    rep.notes.push_back(
        rep.light_from_scene
            ? fmt::format("shadow rays: to the scene's first point light at ({}, {}, {})", p.x, p.y, p.z)
            : fmt::format("shadow rays: the scene has no point light; one placed above the scene (bounds "
                          "centre + camera up x (half height + one diagonal)) at ({}, {}, {})",
                          p.x, p.y, p.z));
    progress(fmt::format("rays: {}x{} primary rays in 4x4 tiles and the rays they spawn", o.width, o.height));
    sets = make_bench_rays(scene, *ours, rep.light, o.width, o.height, o.seed);
    for (BenchRayKind kind : o.kinds) {
      const bool shadow = kind == BenchRayKind::kShadow;
      specs.push_back({bench_ray_kind_name(kind), sets[kind].rays, !shadow, kind != BenchRayKind::kDiffuse});
    }
  }

  // Agreement first: a fast wrong answer is worth nothing.
  std::vector<std::unique_ptr<SetRun>> runs;
  bool agreed = true;
  for (const SetSpec& spec : specs) {
    progress(fmt::format("verify: {} rays ({})", spec.name, spec.rays.size()));
    runs.push_back(std::make_unique<SetRun>(spec, *ours, ref.get(), threads));
    rep.sets.push_back(runs.back()->verify(g));
    agreed = agreed && rep.sets.back().single.disagreements == 0 && rep.sets.back().packet.disagreements == 0;
  }
  if (!agreed) throw BenchDisagreement(disagreement_message(rep));

  for (std::size_t i = 0; i < specs.size(); ++i) {
    progress(fmt::format("time: {} rays", specs[i].name));
    rep.sets[i].single_mrays = runs[i]->time(Way::kSingle, o.repeats);
    if (specs[i].packets) rep.sets[i].packet_mrays = runs[i]->time(Way::kPacket, o.repeats);
  }
  if (!specs.empty()) {
    rep.last_set = specs.back().name;
    rep.last_rays.assign(specs.back().rays.begin(), specs.back().rays.end());
    rep.last_hits = runs.back()->closest_hits();
  }
  return rep;
}

}  // namespace raylab
