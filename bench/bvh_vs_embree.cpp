/// \file
/// bvh_vs_embree: raylab's BVH against Embree 3 on one OBJ mesh, single rays only.
///
///   bvh_vs_embree MESH.obj [--accel bvh|bvh2] [--width 1024] [--height 768] [--repeats 5] [--threads 1] [--json FILE]
///
/// Builds both structures over the same triangles, checks that their primary hits agree, then times
/// primary and shadow rays interleaved (ours, Embree, ours, ...) so that clock or thermal drift hits
/// both alike. `--threads` caps every parallel part (both builds through oneTBB, and the tracing).
/// Exit codes: 0 success, 1 bad input or Embree failure, 2 bad usage, 3 the two structures disagree.

#include <embree3/rtcore.h>
#include <fmt/core.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "raylab/accel/factory.h"
#include "raylab/io/obj_loader.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/camera.h"
#include "raylab/scene/scene.h"

namespace {

using raylab::Hit;
using raylab::Ray;
using raylab::Vec3;
using Rays = std::vector<Ray>;
using Hits = std::vector<Hit>;
using Flags = std::vector<std::uint8_t>;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kRelTol = 1e-4;  // relative tolerance on t between the two structures

struct Options {
  std::string mesh, json;
  std::string accel = "bvh";  // raylab structure to compare, by factory name
  int width = 1024, height = 768, repeats = 5, threads = 1;
};

[[noreturn]] void usage_error(const std::string& message) {
  fmt::print(stderr, "bvh_vs_embree: {}\nusage: bvh_vs_embree MESH.obj [--width 1024] [--height 768] ", message);
  fmt::print(stderr, "[--repeats 5] [--threads 1] [--accel bvh|bvh2] [--json FILE]\n");
  std::exit(2);
}

/// Parses the command line; a malformed or out-of-range value is a usage error (exit 2).
Options parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const std::string names[] = {"--width", "--height", "--repeats", "--threads"};
    int* const numbers[] = {&o.width, &o.height, &o.repeats, &o.threads};
    const auto at = std::find(std::begin(names), std::end(names), arg) - std::begin(names);
    int* number = at < 4 ? numbers[at] : nullptr;
    if (!arg.starts_with("--")) {
      if (!o.mesh.empty()) usage_error("more than one mesh given");
      o.mesh = arg;
    } else if (i + 1 >= argc) {
      usage_error(arg + " needs a value");
    } else if (arg == "--json") {
      o.json = argv[++i];
    } else if (arg == "--accel") {
      o.accel = argv[++i];
      if (o.accel != "bvh" && o.accel != "bvh2") usage_error("--accel wants bvh or bvh2, not '" + o.accel + "'");
    } else if (!number) {
      usage_error("unknown option " + arg);
    } else {
      const std::string value = argv[++i];
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), *number);
      if (ec != std::errc() || end != value.data() + value.size() || *number < 1 || *number > 65536)
        usage_error(arg + " wants an integer in [1, 65536], not '" + value + "'");
    }
  }
  if (o.mesh.empty()) usage_error("no mesh given");
  return o;
}

/// Median seconds of `repeats` alternating runs of `ours` and `embree`: interleaving spreads clock,
/// thermal and neighbour-load drift over both instead of penalising whichever ran second.
template <class A, class B>
std::pair<double, double> time_interleaved(int repeats, const A& ours, const B& embree) {
  auto seconds = [](const auto& fn) {
    const auto start = std::chrono::steady_clock::now();
    fn();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  auto median = [](std::vector<double> v) {  // the upper median for an even count
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  std::vector<double> a, b;
  for (int r = 0; r < repeats; ++r) a.push_back(seconds(ours)), b.push_back(seconds(embree));
  return {median(a), median(b)};
}

/// Calls fn(begin, end) over chunks of [0, n) on `threads` threads (the caller is one of them),
/// handed out dynamically because hit and miss regions of the image cost very different amounts.
template <class Fn>
void parallel_chunks(std::size_t n, int threads, const Fn& fn) {
  if (threads == 1) return fn(std::size_t{0}, n);
  constexpr std::size_t kChunk = 1024;
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t b; (b = next.fetch_add(kChunk, std::memory_order_relaxed)) < n;) fn(b, std::min(n, b + kChunk));
  };
  std::vector<std::jthread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
}

void embree_error(void*, RTCError code, const char* what) { fmt::print(stderr, "embree: {} ({})\n", what, int(code)); }

/// Embree's memory monitor: a net sum (frees come as negative sizes), so after a build it holds what
/// the finished scene keeps, like Bvh::info().memory_bytes. Atomic: Embree builds in parallel.
bool count_bytes(void* sum, ssize_t n, bool) { return static_cast<std::atomic<long long>*>(sum)->fetch_add(n), true; }

/// The triangle soup as Embree buffers: raylab's triangles (9 packed floats: 3 vertices) copied with
/// one spare element, as Embree reads each vertex with a 16-byte load that would overrun the last.
struct EmbreeMesh {
  static_assert(sizeof(raylab::Triangle) == 9 * sizeof(float), "vertex buffer needs packed triangles");
  std::vector<raylab::Triangle> vertices;
  std::vector<unsigned> indices;
  explicit EmbreeMesh(const std::vector<raylab::Triangle>& tris) : vertices(tris), indices(tris.size() * 3) {
    vertices.emplace_back();  // the spare element
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<unsigned>(i);
  }
};

/// Builds an Embree scene over `mesh` with shared buffers (so the timed part is the BVH build only,
/// like ours, which refers to the existing Geometry). Geometry id 0; primitive id = raylab prim id.
RTCScene build_embree_scene(RTCDevice device, const EmbreeMesh& mesh, RTCSceneFlags flags = RTC_SCENE_FLAG_NONE) {
  const std::size_t triangles = mesh.indices.size() / 3;
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, flags);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_MEDIUM);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.vertices.data(), 0,
                             3 * sizeof(float), triangles * 3);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                             3 * sizeof(unsigned), triangles);
  rtcCommitGeometry(geom);
  rtcAttachGeometryByID(scene, geom, 0);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
  return scene;
}

/// Primary rays through pixel centres in 4x4 tiles (tile by tile, row-major inside a tile), the
/// order a tiled renderer traces them in; partial tiles at the right and bottom edges are clipped.
Rays primary_rays(const raylab::Camera& camera, int width, int height) {
  Rays rays;
  rays.reserve(static_cast<std::size_t>(width) * height);
  for (int ty = 0; ty < height; ty += 4)
    for (int tx = 0; tx < width; tx += 4)
      for (int y = ty; y < std::min(ty + 4, height); ++y)
        for (int x = tx; x < std::min(tx + 4, width); ++x) {
          rays.push_back(camera.generate(x + 0.5f, y + 0.5f));
          rays.back().tmin = 0.f, rays.back().tmax = kInf;
        }
  return rays;
}

RTCRay to_embree(const Ray& r) {
  RTCRay e{};  // time, id and flags 0
  e.org_x = r.origin.x, e.org_y = r.origin.y, e.org_z = r.origin.z, e.tnear = r.tmin;
  e.dir_x = r.direction.x, e.dir_y = r.direction.y, e.dir_z = r.direction.z, e.tfar = r.tmax, e.mask = ~0u;
  return e;
}

/// The four timed kernels: closest hit (`out` of Hit) or any hit (`out` of flags), by our BVH or by
/// Embree (`accel` an RTCScene). Every result is stored, so both sides do the same writes and no work
/// is optimised away. Embree's context is set up per chunk, as a renderer would per tile.
template <class Accel, class Out>
void trace(const Accel& accel, const Rays& rays, std::vector<Out>& out, int threads) {
  constexpr bool kEmbree = std::is_same_v<Accel, RTCScene>, kClosest = std::is_same_v<Out, Hit>;
  parallel_chunks(rays.size(), threads, [&](std::size_t b, std::size_t e) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t i = b; i < e; ++i) {
      if constexpr (!kEmbree && kClosest) {
        Ray r = rays[i];  // intersect shrinks tmax, so trace a copy
        out[i] = Hit{};
        accel.intersect(r, out[i]);
      } else if constexpr (!kEmbree) {
        out[i] = accel.occluded(rays[i]);
      } else if constexpr (kClosest) {
        RTCRayHit rh{to_embree(rays[i]), {}};
        rh.hit.geomID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(accel, &context, &rh);
        out[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? Hit{} : Hit{rh.ray.tfar, rh.hit.primID, rh.hit.u, rh.hit.v};
      } else {
        RTCRay r = to_embree(rays[i]);
        rtcOccluded1(accel, &context, &r);
        out[i] = r.tfar < 0.f;  // Embree sets tfar to -inf on an occlusion
      }
    }
  });
}

bool close(double a, double b) { return std::fabs(a - b) <= kRelTol * std::max(std::fabs(a), std::fabs(b)); }

/// Distance along `ray` to triangle `prim` by raylab's own test, or to its plane where the watertight
/// test rejects the hit (a point on an edge the neighbour owns); NaN for an id that is no triangle.
float t_of(const raylab::Geometry& g, const Ray& ray, unsigned prim) {
  if (prim >= g.triangles.size()) return std::numeric_limits<float>::quiet_NaN();
  const raylab::Triangle& tri = g.triangles[prim];
  float t = kInf, u = 0.f, v = 0.f;
  if (raylab::intersect_triangle(tri, raylab::WatertightRay(ray), 0.f, kInf, t, u, v)) return t;
  const Vec3 n = raylab::triangle_normal(tri);
  return raylab::dot(tri.p0 - ray.origin, n) / raylab::dot(ray.direction, n);
}

/// Outcome of comparing the two structures' primary hits ray by ray.
struct Agreement {
  std::size_t hits = 0, misses = 0, same_prim = 0, ties = 0, cracks = 0;  // agreeing rays
  std::size_t hit_miss = 0, t_mismatch = 0, prim_mismatch = 0;            // real disagreements
  std::size_t disagreements() const { return hit_miss + t_mismatch + prim_mismatch; }
};

/// Compares ray by ray. Where prim ids differ but t agrees, Embree's triangle is measured with
/// raylab's test (`t_of`): the same t means both triangles touch the hit point (shared edge, coplanar
/// faces), a tie; else Embree named a wrong primitive. Embree's default test is not watertight, so
/// where only `robust` (RTC_SCENE_FLAG_ROBUST) agrees with ours the ray slipped through an edge crack.
Agreement compare(const raylab::Geometry& g, const Rays& rays, const Hits& ours, const Hits& embree,
                  const Hits& robust) {
  Agreement a;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Hit &o = ours[i], &e = embree[i];
    auto same_t = [&](const Hit& x) { return o.valid() == x.valid() && (!o.valid() || close(o.t, x.t)); };
    const std::size_t before = a.disagreements();
    a.hits += o.valid() && e.valid();
    ++(!same_t(e) && same_t(robust[i])           ? a.cracks
       : o.valid() != e.valid()                  ? a.hit_miss
       : !o.valid()                              ? a.misses
       : !close(o.t, e.t)                        ? a.t_mismatch
       : o.prim_id == e.prim_id                  ? a.same_prim
       : close(o.t, t_of(g, rays[i], e.prim_id)) ? a.ties
                                                 : a.prim_mismatch);
    if (a.disagreements() > before && a.disagreements() <= 5)  // the first few, to debug from
      fmt::print(stderr, "  ray {}: ours t {} prim {}; embree t {} prim {}\n", i, o.t, o.prim_id, e.t, e.prim_id);
  }
  return a;
}

/// One shadow ray per primary hit, towards the light and stopping just short of it. The origin is
/// pushed off the surface along the geometric normal, on the side the primary ray came from, so the
/// ray cannot re-hit its own triangle; `offset` scales with the scene, so no mesh unit is assumed.
Rays shadow_rays(const raylab::Geometry& g, const Rays& rays, const Hits& hits, Vec3 light, float offset) {
  Rays out;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (!hits[i].valid() || hits[i].prim_id >= g.triangles.size()) continue;
    Vec3 n = raylab::normalize(raylab::triangle_normal(g.triangles[hits[i].prim_id]));
    if (raylab::dot(n, rays[i].direction) > 0.f) n = -n;
    Ray s;
    s.origin = rays[i].at(hits[i].t) + n * offset;
    s.direction = light - s.origin;
    s.tmin = 0.f, s.tmax = 0.999f;
    out.push_back(s);
  }
  return out;
}

/// One row of the results: the same figure for both structures.
struct Figure {
  const char *key, *label;  // JSON name, table label
  double ours, embree;
};

/// The whole benchmark; returns the exit code.
int run(const Options& opt) {
  // One cap for both builders: Embree's TBB tasking and raylab's oneTBB builder both honour it.
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(opt.threads));

  raylab::Scene scene;
  scene.add_material({});
  scene.add_object("mesh", 0);
  const raylab::MeshLoadReport report = raylab::load_obj(opt.mesh, scene, 0);
  if (scene.geometry.triangles.empty()) throw std::runtime_error(opt.mesh + ": no triangles");
  raylab::fit_camera_and_lights(scene);
  const raylab::Geometry& geometry = scene.geometry;
  const double tris = double(geometry.triangles.size());
  fmt::print("mesh     {}: {} triangles ({} degenerate dropped); {}x{} rays, {} threads, {} repeats\n", opt.mesh,
             geometry.triangles.size(), report.degenerate_dropped, opt.width, opt.height, opt.threads, opt.repeats);

  RTCDevice device = rtcNewDevice(nullptr);
  if (!device)
    return fmt::print(stderr, "bvh_vs_embree: rtcNewDevice failed (error {})\n", int(rtcGetDeviceError(nullptr))), 1;
  rtcSetDeviceErrorFunction(device, embree_error, nullptr);
  std::atomic<long long> embree_allocated{0};
  rtcSetDeviceMemoryMonitorFunction(device, count_bytes, &embree_allocated);

  // Builds, alternating like the traces; the last of each is kept for tracing. Each side frees its
  // previous build first, so neither builds with the other's garbage in the allocator.
  const EmbreeMesh mesh(geometry.triangles);
  std::unique_ptr<raylab::Accelerator> bvh;
  RTCScene escene = nullptr;
  long long embree_bytes = 0;
  const auto [ours_build, embree_build] = time_interleaved(
      opt.repeats, [&] { bvh = nullptr, bvh = raylab::make_accelerator(opt.accel, geometry); },
      [&] {
        if (escene) rtcReleaseScene(escene);
        embree_allocated = 0;  // after the release: only this build's bytes count
        escene = build_embree_scene(device, mesh);
        embree_bytes = embree_allocated;
      });

  // Rays, then a verification pass (which doubles as the warm-up of the timed passes).
  const Rays rays = primary_rays(raylab::Camera(scene.camera, opt.width, opt.height), opt.width, opt.height);
  Hits ours_hits(rays.size()), embree_hits(rays.size()), robust_hits(rays.size());
  trace(*bvh, rays, ours_hits, opt.threads);
  trace(escene, rays, embree_hits, opt.threads);
  RTCScene robust = build_embree_scene(device, mesh, RTC_SCENE_FLAG_ROBUST);
  trace(robust, rays, robust_hits, opt.threads);
  rtcReleaseScene(robust);
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE) return fmt::print(stderr, "bvh_vs_embree: Embree failed\n"), 1;
  const Agreement agree = compare(geometry, rays, ours_hits, embree_hits, robust_hits);
  fmt::print("verify   {} primary rays: {} hits ({} same prim, {} ties), {} misses, {} Embree edge cracks; ",
             rays.size(), agree.hits, agree.same_prim, agree.ties, agree.misses, agree.cracks);
  fmt::print("disagreements: {} hit/miss, {} t, {} prim\n", agree.hit_miss, agree.t_mismatch, agree.prim_mismatch);
  if (agree.disagreements() != 0) {
    fmt::print(stderr, "bvh_vs_embree: FAILED: raylab's BVH and Embree disagree on {} of {} primary rays\n",
               agree.disagreements(), rays.size());
    return 3;
  }

  const float diagonal = raylab::length(geometry.bounds().extent());
  const bool has_point = !scene.lights.empty() && scene.lights[0].kind != raylab::Light::Kind::kDirectional;
  const Vec3 light = has_point ? scene.lights[0].position  // else a point above the camera
                               : scene.camera.from + raylab::normalize(scene.camera.up) * diagonal;
  const Rays shadows = shadow_rays(geometry, rays, ours_hits, light, 1e-4f * diagonal);
  Flags ours_occ(shadows.size()), embree_occ(shadows.size());
  trace(*bvh, shadows, ours_occ, opt.threads);
  trace(escene, shadows, embree_occ, opt.threads);
  std::size_t occluded = 0, occ_mismatch = 0;
  for (std::size_t i = 0; i < shadows.size(); ++i)
    occluded += ours_occ[i], occ_mismatch += ours_occ[i] != embree_occ[i];
  // Not fatal: a shadow ray grazing a silhouette or through an edge may legitimately go either way.
  fmt::print("shadow   {} rays, {} occluded; {} occlusion disagreements\n\n", shadows.size(), occluded, occ_mismatch);

  const auto [ours_primary, embree_primary] = time_interleaved(
      opt.repeats, [&] { trace(*bvh, rays, ours_hits, opt.threads); },
      [&] { trace(escene, rays, embree_hits, opt.threads); });
  const auto [ours_shadow, embree_shadow] = time_interleaved(
      opt.repeats, [&] { trace(*bvh, shadows, ours_occ, opt.threads); },
      [&] { trace(escene, shadows, embree_occ, opt.threads); });
  rtcReleaseScene(escene);
  rtcReleaseDevice(device);

  const double n = double(rays.size()), ns = double(shadows.size());
  const Figure figures[] = {
      {"build_ms", "build ms", ours_build * 1e3, embree_build * 1e3},
      {"build_mprims_s", "build Mprims/s", tris / ours_build / 1e6, tris / embree_build / 1e6},
      {"bytes_per_triangle", "bytes/triangle", double(bvh->info().memory_bytes) / tris, embree_bytes / tris},
      {"primary_mrays_s", "primary Mrays/s", n / ours_primary / 1e6, n / embree_primary / 1e6},
      {"shadow_mrays_s", "shadow Mrays/s", ns / ours_shadow / 1e6, ns / embree_shadow / 1e6}};
  fmt::print("{:<20}{:>12}{:>12}{:>14}\n", "", "raylab " + opt.accel, "embree 3", "ours/embree");
  for (const Figure& f : figures)
    fmt::print("{:<20}{:>12.2f}{:>12.2f}{:>14.3f}\n", f.label, f.ours, f.embree, f.ours / f.embree);

  if (opt.json.empty()) return 0;
  std::FILE* out = std::fopen(opt.json.c_str(), "w");
  if (!out) throw std::runtime_error(opt.json + ": cannot open for writing");
  fmt::print(out,
             "{{\"mesh\": {:?}, \"triangles\": {}, \"width\": {}, \"height\": {}, \"repeats\": {}, \"threads\": {}, "
             "\"primary_rays\": {}, \"hits\": {}, \"same_prim\": {}, \"ties\": {}, \"embree_cracks\": {}, "
             "\"shadow_rays\": {}, \"occluded\": {}, \"occlusion_disagreements\": {}",
             opt.mesh, geometry.triangles.size(), opt.width, opt.height, opt.repeats, opt.threads, rays.size(),
             agree.hits, agree.same_prim, agree.ties, agree.cracks, shadows.size(), occluded, occ_mismatch);
  for (const Figure& f : figures)
    fmt::print(out, ",\n \"{}\": {{\"ours\": {}, \"embree\": {}, \"ratio\": {}}}", f.key, f.ours, f.embree,
               f.ours / f.embree);
  fmt::print(out, "\n}}\n");
  if (std::fclose(out) != 0) throw std::runtime_error(opt.json + ": write failed");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse_args(argc, argv);
  try {
    return run(options);
  } catch (const std::exception& e) {
    fmt::print(stderr, "bvh_vs_embree: {}\n", e.what());
    return 1;
  }
}
