// Whether the path integrator's next-event shadow rays pay to be traced together (issue 30, item
// 7): an upper bound at the kernel level, before any change to the integrator. The program
// renders a scene once with the path integrator on one thread through a recording accelerator,
// which keeps every shadow ray in the order it was cast and notes where each tile ends. It then
// times, interleaved (one repeat of every variant after another, medians), the recorded rays
// traced
//   single     one by one (Accelerator::occluded(const Ray&)), in recorded order: what the
//              integrator does now;
//   tile16     through the group any-hit (occluded(span, span)) in chunks of 16 (the wide BVH's
//              packet size), in recorded order per tile;
//   tile       the same with each tile's rays as one stream (the kernel cuts it into runs of up
//              to 16 consecutive rays of one direction octant);
//   origin*    each tile's rays sorted by direction octant and then by the 30-bit Morton code of
//              their origin, in chunks of 16, 256 or as one stream;
//   dir        sorted by octant and then by the Morton code of the direction, one stream;
//   coarse     sorted by octant and a 12-bit Morton code of the origin (two radix passes), one
//              stream: the sort an integrator could afford;
// and the sorts on their own (key, sort and gathering the rays, into reused buffers). It checks
// that every variant answers as the render did, ray for ray (sorts undone). In the same loop it
// renders twice more: shadow rays traced, and the recorded answers replayed instead (the
// integrator takes the very same branches, as a shadow ray's answer changes only what is added,
// not the path): the difference is the shadow rays' share of the render, and
// end-to-end gain <= share * (1 - 1 / speedup).
//
//   raylab_shadow_grouping SCENE WIDTH HEIGHT SPP REPEATS [ENV]
//
// ENV is an environment colour R,G,B as `raylab render --env` takes it ("-" or absent: none).
// Single thread throughout; the accelerator is the one `raylab render` builds by default.

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "raylab/accel/two_level.h"
#include "raylab/io/render_overrides.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/renderer.h"

namespace {

using namespace raylab;
using Clock = std::chrono::steady_clock;

/// What RecordingAccel does with shadow rays.
enum class ShadowMode {
  kRecord,  ///< trace each, keep it and its answer
  kTrace,   ///< trace each, keep nothing (the cost of the render as it is, plus one forwarding call)
  kReplay,  ///< trace none: return the recorded answers in order
};

/// An accelerator that forwards every query to `inner` and, for the single shadow-ray queries the
/// path integrator makes, records or replays them (ShadowMode). One thread only: the recording
/// is in cast order, which is tile order only when the tiles are rendered one after another.
class RecordingAccel final : public Accelerator {
 public:
  /// Forwards to `inner`, which must outlive this object.
  explicit RecordingAccel(const Accelerator& inner) : m_inner(inner) {}

  /// The shadow rays recorded, in the order they were cast.
  std::vector<Ray> rays;
  /// The answer `inner` gave for each of `rays` (1: occluded).
  std::vector<std::uint8_t> answers;
  /// Where each tile's rays end in `rays` (one past its last).
  std::vector<std::size_t> tile_ends;
  /// What the shadow queries do.
  ShadowMode mode = ShadowMode::kRecord;

  /// Starts a replay of `answers` from the first.
  void rewind() { m_next = 0; }
  /// Answers replayed since the last rewind().
  std::size_t replayed() const { return m_next; }

  /// Bounds of `inner`.
  Box3 bounds() const override { return m_inner.bounds(); }
  /// Forwarded.
  bool intersect(Ray& ray, Hit& hit) const override { return m_inner.intersect(ray, hit); }
  /// Recorded, traced or replayed as `mode` says.
  bool occluded(const Ray& ray) const override { return shadow(ray, nullptr); }
  /// Forwarded.
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const override {
    return m_inner.intersect_counted(ray, hit, stats);
  }
  /// Recorded, traced or replayed as `mode` says.
  bool occluded_counted(const Ray& ray, TraversalStats& stats) const override { return shadow(ray, &stats); }
  /// Forwarded (camera ray packets).
  void intersect(std::span<Ray> group, std::span<Hit> hits) const override { m_inner.intersect(group, hits); }
  /// Forwarded: the path integrator casts no shadow-ray groups (only the Whitted one does).
  void occluded(std::span<const Ray> group, std::span<std::uint8_t> out) const override {
    m_inner.occluded(group, out);
  }
  /// Forwarded.
  void all_hits(const Ray& ray, std::vector<Hit>& hits) const override { m_inner.all_hits(ray, hits); }
  /// Forwarded.
  AccelInfo info() const override { return m_inner.info(); }

 private:
  // The vectors are written from a const query: the recorder is the one thing this wrapper is
  // for, and render() only hands out a const Accelerator.
  bool shadow(const Ray& ray, TraversalStats* stats) const {
    auto& self = const_cast<RecordingAccel&>(*this);
    switch (mode) {
      case ShadowMode::kReplay:
        // Past the end only if the render cast other rays than it recorded: a broken replay.
        if (m_next >= answers.size()) std::abort();
        return answers[self.m_next++] != 0;
      case ShadowMode::kTrace:
        return stats ? m_inner.occluded_counted(ray, *stats) : m_inner.occluded(ray);
      case ShadowMode::kRecord:
        break;
    }
    const bool blocked = stats ? m_inner.occluded_counted(ray, *stats) : m_inner.occluded(ray);
    self.rays.push_back(ray);
    self.answers.push_back(blocked ? 1 : 0);
    return blocked;
  }

  const Accelerator& m_inner;
  std::size_t m_next = 0;
};

/// Seconds `fn` takes once.
double seconds_of(const std::function<void()>& fn) {
  const auto start = Clock::now();
  fn();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The median of `v` (upper middle for an even count).
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Spreads the low 10 bits of `x` to every third bit.
std::uint32_t spread_bits(std::uint32_t x) {
  x &= 0x3ffu;
  x = (x | (x << 16)) & 0x030000ffu;
  x = (x | (x << 8)) & 0x0300f00fu;
  x = (x | (x << 4)) & 0x030c30c3u;
  x = (x | (x << 2)) & 0x09249249u;
  return x;
}

/// The 30-bit Morton code of `p` quantised to 10 bits per axis within [lo, hi].
std::uint32_t morton(Vec3 p, Vec3 lo, Vec3 hi) {
  std::uint32_t code = 0;
  for (int a = 0; a < 3; ++a) {
    const float extent = hi[a] - lo[a];
    const float f = extent > 0.f ? (p[a] - lo[a]) / extent : 0.f;
    const auto q = static_cast<std::uint32_t>(std::clamp(f, 0.f, 1.f) * 1023.f);
    code |= spread_bits(q) << a;
  }
  return code;
}

/// How a tile's rays are ordered before the group query.
enum class SortKey {
  kOrigin,     ///< octant, then 30-bit Morton code of the origin (std::sort of 64-bit keys)
  kDirection,  ///< octant, then 30-bit Morton code of the direction (std::sort)
  kCoarse,     ///< octant, then 12-bit Morton code of the origin: two radix passes, the cheap sort
};

/// The permutation of rays[begin, end) sorted by (direction octant, Morton code of the origin in
/// `bounds` or of the direction in [-1, 1]^3), as indices into `rays`, appended to `order`.
void sort_tile(std::span<const Ray> rays, std::size_t begin, std::size_t end, const Box3& bounds, SortKey key,
               std::vector<std::uint64_t>& keys, std::vector<std::uint32_t>& order) {
  keys.clear();
  for (std::size_t i = begin; i < end; ++i) {
    const Ray& r = rays[i];
    const std::uint32_t code =
        key == SortKey::kOrigin ? morton(r.origin, bounds.lo, bounds.hi) : morton(r.direction, Vec3{-1.f}, Vec3{1.f});
    // octant (3 bits) | code (30 bits) | index within the tile (the sort is then total).
    keys.push_back((std::uint64_t{static_cast<std::uint32_t>(direction_octant(r.direction))} << 61) |
                   (std::uint64_t{code} << 31) | (i - begin));
  }
  std::sort(keys.begin(), keys.end());
  for (std::uint64_t k : keys) order.push_back(static_cast<std::uint32_t>(begin + (k & 0x7fffffffu)));
}

/// As sort_tile, with 15-bit keys (octant, 4 bits per axis of the origin) sorted by two stable
/// 8-bit radix passes: what an integrator could afford per tile. Tiles of at most 2^16 rays.
void sort_tile_radix(std::span<const Ray> rays, std::size_t begin, std::size_t end, const Box3& bounds,
                     std::vector<std::uint32_t>& a, std::vector<std::uint32_t>& b, std::vector<std::uint32_t>& order) {
  const std::size_t count = end - begin;
  if (count > 0x10000u) std::abort();  // the index within the tile takes the low 16 bits
  a.resize(count);
  b.resize(count);
  // 16 cells per axis: no division per ray, and the 4 bits spread by a table.
  static constexpr std::uint32_t kSpread4[16] = {0x000, 0x001, 0x008, 0x009, 0x040, 0x041, 0x048, 0x049,
                                                 0x200, 0x201, 0x208, 0x209, 0x240, 0x241, 0x248, 0x249};
  float scale[3];
  for (int k = 0; k < 3; ++k) {
    const float extent = bounds.hi[k] - bounds.lo[k];
    scale[k] = extent > 0.f ? 16.f / extent : 0.f;
  }
  for (std::size_t i = 0; i < count; ++i) {
    const Ray& r = rays[begin + i];
    std::uint32_t code = 0;
    for (int k = 0; k < 3; ++k) {
      const float f = (r.origin[k] - bounds.lo[k]) * scale[k];
      code |= kSpread4[static_cast<std::uint32_t>(std::clamp(f, 0.f, 15.f))] << k;
    }
    const auto octant = static_cast<std::uint32_t>(direction_octant(r.direction));
    a[i] = (((octant << 12) | code) << 16) | static_cast<std::uint32_t>(i);
  }
  for (int shift : {16, 24}) {
    std::uint32_t offset[257] = {};
    for (std::uint32_t v : a) ++offset[((v >> shift) & 0xffu) + 1];
    for (int d = 0; d < 256; ++d) offset[d + 1] += offset[d];
    for (std::uint32_t v : a) b[offset[(v >> shift) & 0xffu]++] = v;
    a.swap(b);
  }
  for (std::uint32_t v : a) order.push_back(static_cast<std::uint32_t>(begin + (v & 0xffffu)));
}

/// The permutation of every tile's rays sorted within the tile (sort_tile), and the rays in it.
struct SortedRays {
  std::vector<std::uint32_t> order;  ///< sorted position -> recorded index
  std::vector<Ray> rays;             ///< the rays in sorted order
};

/// Sorts each tile's rays by `key` into `s`, whose buffers are reused (as an integrator sorting
/// tile after tile would reuse them), so that the sort's timing holds no allocation.
void sort_by_tile(const RecordingAccel& rec, const Box3& bounds, SortKey key, SortedRays& s) {
  s.order.clear();
  s.order.reserve(rec.rays.size());
  thread_local std::vector<std::uint64_t> keys;
  thread_local std::vector<std::uint32_t> a, b;
  std::size_t begin = 0;
  for (std::size_t end : rec.tile_ends) {
    if (key == SortKey::kCoarse) {
      sort_tile_radix(rec.rays, begin, end, bounds, a, b, s.order);
    } else {
      sort_tile(rec.rays, begin, end, bounds, key, keys, s.order);
    }
    begin = end;
  }
  s.rays.resize(s.order.size());
  for (std::size_t i = 0; i < s.order.size(); ++i) s.rays[i] = rec.rays[s.order[i]];
}

/// Sorts each tile's rays by `key`.
SortedRays sort_by_tile(const RecordingAccel& rec, const Box3& bounds, SortKey key) {
  SortedRays s;
  sort_by_tile(rec, bounds, key, s);
  return s;
}

/// Traces each tile of `rays` (ends in `tile_ends`) through the group any-hit in chunks of at
/// most `chunk` rays (0: the whole tile as one group).
void trace_groups(const Accelerator& accel, std::span<const Ray> rays, const std::vector<std::size_t>& tile_ends,
                  std::size_t chunk, std::span<std::uint8_t> out) {
  std::size_t begin = 0;
  for (std::size_t end : tile_ends) {
    const std::size_t step = chunk == 0 ? end - begin : chunk;
    for (std::size_t b = begin; b < end; b += step) {
      const std::size_t e = std::min(end, b + step);
      accel.occluded(rays.subspan(b, e - b), out.subspan(b, e - b));
    }
    begin = end;
  }
}

/// A timed way of answering the recorded rays.
struct Variant {
  std::string name;             ///< as the table prints it
  std::function<void()> run;    ///< one timed run
  std::vector<double> seconds;  ///< each repeat's time
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6 && argc != 7) {
    fmt::print(stderr, "usage: raylab_shadow_grouping SCENE WIDTH HEIGHT SPP REPEATS [ENV]\n");
    return 2;
  }
  LoadOptions load;
  load.allow_outside_paths = true;  // the bench meshes live beside the repository
  Scene scene = load_scene(argv[1], load);
  SettingsOverride over;
  over.width = std::atoi(argv[2]);
  over.height = std::atoi(argv[3]);
  over.spp = std::atoi(argv[4]);
  over.integrator = "path";
  if (argc == 7 && std::string(argv[6]) != "-") over.environment = argv[6];
  apply_render_overrides(scene, over, CameraOverride{});
  const int repeats = std::max(1, std::atoi(argv[5]));

  // The accelerator `raylab render` builds by default.
  const std::unique_ptr<Accelerator> accel =
      make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, SceneAccelOptions{});
  const Box3 bounds = accel->bounds();

  RecordingAccel rec(*accel);
  RenderOptions options;
  options.threads = 1;  // tiles one after another: the recording is in tile order
  options.on_progress = [&rec](int, int) { rec.tile_ends.push_back(rec.rays.size()); };
  {
    Film film(scene.settings.width, scene.settings.height);
    const RenderResult r = render(scene, rec, film, options);
    fmt::print("scene {} {}x{} {} spp, max depth {}, accelerator {}: {} shadow rays in {} tiles ({:.1f}% blocked)\n",
               argv[1], scene.settings.width, scene.settings.height, scene.settings.spp, scene.settings.max_depth,
               accel->info().name, rec.rays.size(), rec.tile_ends.size(),
               100.0 * static_cast<double>(std::count(rec.answers.begin(), rec.answers.end(), 1)) /
                   static_cast<double>(std::max<std::size_t>(1, rec.answers.size())));
    fmt::print("render rays: {} primary, {} shadow, {} bounce\n", r.stats.rays[int(RayKind::kPrimary)],
               r.stats.rays[int(RayKind::kShadow)], r.stats.rays[int(RayKind::kReflection)]);
  }
  options.on_progress = nullptr;
  const std::size_t n = rec.rays.size();
  if (n == 0) {
    fmt::print("no shadow rays\n");
    return 1;
  }

  // How coherent recorded order already is: the packets the kernel would form per tile.
  auto count_runs = [&](std::span<const Ray> rays) {
    std::size_t runs = 0, begin = 0;
    for (std::size_t end : rec.tile_ends) {
      for (std::size_t i = begin; i < end;) {
        const int o = direction_octant(rays[i].direction);
        std::size_t j = i + 1;
        while (j < end && j - i < 16 && direction_octant(rays[j].direction) == o) ++j;
        ++runs;
        i = j;
      }
      begin = end;
    }
    return runs;
  };

  const SortedRays by_origin = sort_by_tile(rec, bounds, SortKey::kOrigin);
  const SortedRays by_direction = sort_by_tile(rec, bounds, SortKey::kDirection);
  const SortedRays by_coarse = sort_by_tile(rec, bounds, SortKey::kCoarse);
  fmt::print("mean rays per octant packet: recorded {:.2f}, sorted {:.2f}\n",
             static_cast<double>(n) / static_cast<double>(count_runs(rec.rays)),
             static_cast<double>(n) / static_cast<double>(count_runs(by_origin.rays)));

  std::vector<std::uint8_t> out_single(n), out_tile16(n), out_tile(n), out_origin(n), out_dir(n), out_coarse(n),
      out_origin16(n), out_origin256(n);
  std::vector<Variant> variants;
  auto add = [&variants](std::string name, std::function<void()> run) {
    variants.push_back(Variant{std::move(name), std::move(run), {}});
  };
  add("single", [&] {
    for (std::size_t i = 0; i < n; ++i) out_single[i] = accel->occluded(rec.rays[i]) ? 1 : 0;
  });
  add("tile16", [&] { trace_groups(*accel, rec.rays, rec.tile_ends, 16, out_tile16); });
  add("tile", [&] { trace_groups(*accel, rec.rays, rec.tile_ends, 0, out_tile); });
  add("origin16", [&] { trace_groups(*accel, by_origin.rays, rec.tile_ends, 16, out_origin16); });
  add("origin256", [&] { trace_groups(*accel, by_origin.rays, rec.tile_ends, 256, out_origin256); });
  add("origin", [&] { trace_groups(*accel, by_origin.rays, rec.tile_ends, 0, out_origin); });
  add("dir", [&] { trace_groups(*accel, by_direction.rays, rec.tile_ends, 0, out_dir); });
  add("coarse", [&] { trace_groups(*accel, by_coarse.rays, rec.tile_ends, 0, out_coarse); });
  SortedRays scratch;  // the sorts' output, reused from run to run
  add("sort origin", [&] { sort_by_tile(rec, bounds, SortKey::kOrigin, scratch); });
  add("sort dir", [&] { sort_by_tile(rec, bounds, SortKey::kDirection, scratch); });
  add("sort coarse", [&] { sort_by_tile(rec, bounds, SortKey::kCoarse, scratch); });
  // The whole render, shadow rays traced, then replayed: their share of it, in the same loop so
  // that every ratio compares runs made under the same machine load.
  Film film(scene.settings.width, scene.settings.height);
  bool replay_ok = true;
  add("render traced", [&] {
    rec.mode = ShadowMode::kTrace;
    render(scene, rec, film, options);
  });
  add("render replayed", [&] {
    rec.mode = ShadowMode::kReplay;
    rec.rewind();
    render(scene, rec, film, options);
    replay_ok = replay_ok && rec.replayed() == n;
  });

  for (Variant& v : variants) v.run();  // warm-up: caches, page faults
  for (int rep = 0; rep < repeats; ++rep) {
    for (Variant& v : variants) v.seconds.push_back(seconds_of(v.run));
  }

  // Ray for ray against the render's own answers, sorted results put back in recorded order.
  auto mismatches = [&](const std::vector<std::uint8_t>& out, const std::vector<std::uint32_t>* order) {
    std::size_t bad = 0;
    for (std::size_t i = 0; i < n; ++i) bad += out[i] != rec.answers[order ? (*order)[i] : i];
    return bad;
  };
  const std::size_t bad[] = {mismatches(out_single, nullptr),
                             mismatches(out_tile16, nullptr),
                             mismatches(out_tile, nullptr),
                             mismatches(out_origin16, &by_origin.order),
                             mismatches(out_origin256, &by_origin.order),
                             mismatches(out_origin, &by_origin.order),
                             mismatches(out_dir, &by_direction.order),
                             mismatches(out_coarse, &by_coarse.order)};

  const double t_single = median(variants[0].seconds);
  fmt::print("\n| variant | median ms | Mrays/s | speedup vs single (median of per-repeat ratios) | mismatches |\n");
  fmt::print("|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < variants.size() - 2; ++k) {
    const Variant& v = variants[k];
    std::vector<double> ratios;
    for (int rep = 0; rep < repeats; ++rep) ratios.push_back(variants[0].seconds[rep] / v.seconds[rep]);
    const double t = median(v.seconds);
    if (k < std::size(bad)) {
      fmt::print("| {} | {:.2f} | {:.2f} | {:.3f} | {} |\n", v.name, 1e3 * t, 1e-6 * static_cast<double>(n) / t,
                 median(ratios), bad[k]);
    } else {
      fmt::print("| {} | {:.2f} | | {:.3f} of single's time | |\n", v.name, 1e3 * t, t / t_single);
    }
  }

  if (!replay_ok) {
    fmt::print(stderr, "a replayed render cast other shadow rays than the recording\n");
    return 1;
  }
  // Per repeat: the share, and two projections of the end-to-end gain of the cheap sort (coarse)
  // with its sort. `formula`: share * (1 - 1 / speedup), the speedup measured back to back.
  // `replace`: the render's own shadow time (traced - replayed, which costs more per ray than
  // the back-to-back loop: caches hold the shading's data) replaced by the sorted group's time.
  const auto at = [&](const char* name) -> const std::vector<double>& {
    for (const Variant& v : variants) {
      if (v.name == name) return v.seconds;
    }
    std::abort();
  };
  const auto &single = at("single"), &coarse = at("coarse"), &sort = at("sort coarse"), &origin = at("origin"),
             &traced = at("render traced"), &replayed = at("render replayed");
  std::vector<double> share, formula, formula_free, replace, per_ray_render, per_ray_single;
  for (int rep = 0; rep < repeats; ++rep) {
    const double shadow = traced[rep] - replayed[rep];
    share.push_back(shadow / traced[rep]);
    const double speedup = single[rep] / (coarse[rep] + sort[rep]);
    formula.push_back(share.back() * (1.0 - 1.0 / speedup));
    formula_free.push_back(share.back() * (1.0 - origin[rep] / single[rep]));
    replace.push_back((shadow - coarse[rep] - sort[rep]) / traced[rep]);
    per_ray_render.push_back(1e9 * shadow / static_cast<double>(n));
    per_ray_single.push_back(1e9 * single[rep] / static_cast<double>(n));
  }
  fmt::print("\nrender (1 thread): traced {:.3f} s, shadow rays replayed {:.3f} s; shadow share {:.1f}%\n",
             median(traced), median(replayed), 100.0 * median(share));
  fmt::print("shadow ray cost: {:.0f} ns in the render, {:.0f} ns back to back\n", median(per_ray_render),
             median(per_ray_single));
  fmt::print(
      "projected end-to-end gain: {:.1f}% (share x (1 - 1/speedup), coarse sort + group), {:.1f}% (same, "
      "sort free, origin order), {:.1f}% (render's shadow time replaced by coarse sort + group)\n",
      100.0 * median(formula), 100.0 * median(formula_free), 100.0 * median(replace));
  return 0;
}
