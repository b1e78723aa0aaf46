// Is `raylab bench`'s Embree figure the one Embree's users get (issue 31, item 5)? The bench
// traces Embree through EmbreeReference (src/accel/embree_reference.cpp): the triangles as an
// unshared vertex buffer (three vertices per triangle), each Ray converted to an RTCRayHit inside
// the timed loop (through a temporary, tfar nudged below tmax for our [tmin, tmax)) and each
// answer converted back to our Hit. This program times, interleaved in one process (one repeat
// of each after the other, medians), on the same rays:
//   bench   EmbreeReference::intersect1, as `raylab bench` times it;
//   user    what Embree's tutorials do: the record's fields filled from the user's ray right
//           before each rtcIntersect1, on the welded mesh (identical positions share a vertex,
//           as a user's indexed mesh does);
//   plain   rtcIntersect1 over RTCRayHit records prepared before the clock starts (copied from a
//           prepared array each repeat, outside the timing): Embree's best case, and the same
//           footing as our side, which reads a prepared array of Ray;
//   soup    plain on the unshared vertices: what the welding changes;
//   ours    raylab's `bvh` as the bench times it (a copy of each prepared Ray, intersect);
// all on a default device, default flags, medium quality, one thread, and counts the rays on
// which plain or user answer otherwise than the bench (hit or miss, or t not the same float).
//
//   raylab_embree_plain_loop SCENE RAYS_FILE REPEATS
//
// RAYS_FILE: a .rays file, for example the bench's primary rays written by
// `raylab bench SCENE --rays primary --rays-out FILE --against none`. Single thread.

#include <embree3/rtcore.h>
#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "raylab/accel/embree_reference.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/core/hash64.h"
#include "raylab/io/ray_file.h"
#include "raylab/io/scene_loader.h"

namespace {

using raylab::Geometry;
using raylab::Hit;
using raylab::Ray;
using raylab::Vec3;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// The triangles as a user's indexed mesh: each distinct position once (compared bit for bit),
/// three indices per triangle, with one float of padding after the last vertex because Embree
/// reads vertices as 16 bytes.
struct WeldedMesh {
  std::vector<float> positions;  // x, y, z per vertex, plus one padding float
  std::vector<unsigned> indices;
};

WeldedMesh weld(const Geometry& g, bool share = true) {
  struct Key {
    float x, y, z;
    bool operator==(const Key& o) const {
      return std::bit_cast<unsigned>(x) == std::bit_cast<unsigned>(o.x) &&
             std::bit_cast<unsigned>(y) == std::bit_cast<unsigned>(o.y) &&
             std::bit_cast<unsigned>(z) == std::bit_cast<unsigned>(o.z);
    }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      raylab::Hash64 h;  // the project's one hash
      h.word(std::uint64_t{std::bit_cast<std::uint32_t>(k.x)} << 32 | std::bit_cast<std::uint32_t>(k.y));
      h.word(std::bit_cast<std::uint32_t>(k.z));
      return static_cast<std::size_t>(h.value());
    }
  };
  WeldedMesh m;
  std::unordered_map<Key, unsigned, KeyHash> index_of;
  for (const raylab::Triangle& t : g.triangles) {
    for (const Vec3& p : {t.p0, t.p1, t.p2}) {
      if (!share) {
        m.indices.push_back(static_cast<unsigned>(m.positions.size() / 3));
        m.positions.insert(m.positions.end(), {p.x, p.y, p.z});
        continue;
      }
      const auto [it, added] = index_of.try_emplace(Key{p.x, p.y, p.z}, static_cast<unsigned>(index_of.size()));
      if (added) m.positions.insert(m.positions.end(), {p.x, p.y, p.z});
      m.indices.push_back(it->second);
    }
  }
  m.positions.push_back(0.f);
  return m;
}

RTCScene build_welded(RTCDevice device, const WeldedMesh& m) {
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, m.positions.data(), 0,
                             3 * sizeof(float), (m.positions.size() - 1) / 3);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m.indices.data(), 0,
                             3 * sizeof(unsigned), m.indices.size() / 3);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
  return scene;
}

/// The rays as a user keeps them for rtcIntersect1: [tmin, tfar] as given, no nudging.
std::vector<RTCRayHit> embree_records(const std::vector<Ray>& rays) {
  std::vector<RTCRayHit> out(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    RTCRayHit& rh = out[i];
    const Ray& r = rays[i];
    rh.ray.org_x = r.origin.x, rh.ray.org_y = r.origin.y, rh.ray.org_z = r.origin.z, rh.ray.tnear = r.tmin;
    rh.ray.dir_x = r.direction.x, rh.ray.dir_y = r.direction.y, rh.ray.dir_z = r.direction.z, rh.ray.time = 0.f;
    rh.ray.tfar = r.tmax, rh.ray.mask = ~0u, rh.ray.id = 0, rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID, rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  return out;
}

template <class F>
double seconds_of(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int run(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s SCENE RAYS_FILE REPEATS\n", argv[0]);
    return 2;
  }
  const int repeats = std::atoi(argv[3]);
  if (repeats < 1) {
    std::fprintf(stderr, "%s: REPEATS must be a whole number >= 1\n", argv[0]);
    return 2;
  }
  raylab::LoadOptions load;
  load.allow_outside_paths = true;
  const raylab::Scene scene = raylab::load_scene(argv[1], load);
  const Geometry& g = scene.geometry;
  if (g.triangles.empty() || g.size() != g.triangles.size() || !scene.instances.empty()) {
    std::fprintf(stderr, "%s: the scene must be triangles only, without instances\n", argv[0]);
    return 1;
  }
  const std::vector<Ray> rays = raylab::read_rays(argv[2]);

  raylab::EmbreeReference bench_side(g);  // Embree's choice of kernels, as `raylab bench` by default
  const WeldedMesh mesh = weld(g);
  RTCDevice device = rtcNewDevice(nullptr);  // as the bench: Embree picks the kernels
  RTCScene welded = build_welded(device, mesh);
  const WeldedMesh soup = weld(g, false);
  RTCScene unwelded = build_welded(device, soup);
  const std::vector<RTCRayHit> prepared = embree_records(rays);
  std::vector<RTCRayHit> work(prepared.size());
  std::vector<Hit> bench_hits(rays.size());
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);

  const auto ours = raylab::make_accelerator("bvh", g);  // the bench's default structure
  std::vector<Hit> our_hits(rays.size());
  std::vector<double> bench_s, plain_s, welded_s, soup_s, ours_s;
  std::vector<Hit> welded_hits(rays.size());
  for (int r = 0; r < repeats; ++r) {
    bench_s.push_back(seconds_of([&] { bench_side.intersect1(rays, bench_hits); }));
    // Ours as the bench times it: a copy of each prepared Ray, intersect.
    ours_s.push_back(seconds_of([&] {
      for (std::size_t i = 0; i < rays.size(); ++i) {
        Ray copy = rays[i];
        our_hits[i] = Hit{};
        ours->intersect(copy, our_hits[i]);
      }
    }));
    work = prepared;
    plain_s.push_back(seconds_of([&] {
      for (RTCRayHit& rh : work) rtcIntersect1(welded, &context, &rh);
    }));
    std::vector<RTCRayHit> soup_work = prepared;
    soup_s.push_back(seconds_of([&] {
      for (RTCRayHit& rh : soup_work) rtcIntersect1(unwelded, &context, &rh);
    }));
    // What a user's loop does (Embree's tutorials): the record's fields filled from the user's
    // own ray right before the call, the answer read back from it.
    welded_s.push_back(seconds_of([&] {
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray& ray = rays[i];
        RTCRayHit rh;
        rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
        rh.ray.tnear = ray.tmin;
        rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
        rh.ray.time = 0.f, rh.ray.tfar = ray.tmax, rh.ray.mask = ~0u, rh.ray.id = 0, rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID, rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(welded, &context, &rh);
        welded_hits[i] =
            rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? Hit{} : Hit{rh.ray.tfar, rh.hit.primID, rh.hit.u, rh.hit.v};
      }
    }));
  }

  // Agreement: hit or miss and t, against the bench's answers.
  std::size_t hit_count = 0, differ = 0, differ_welded = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const bool b = bench_hits[i].valid(), p = work[i].hit.geomID != RTC_INVALID_GEOMETRY_ID;
    hit_count += b ? 1 : 0;
    if (b != p || (b && bench_hits[i].t != work[i].ray.tfar)) ++differ;
    if (b != welded_hits[i].valid() || (b && bench_hits[i].t != welded_hits[i].t)) ++differ_welded;
  }
  const double mb = median(bench_s), mp = median(plain_s), mw = median(welded_s), ms = median(soup_s);
  const double mo = median(ours_s);
  const double mrays = static_cast<double>(rays.size()) / 1e6;
  fmt::print("{}: {} triangles, {} vertices welded (of {}); {} rays, {} hit; 1 thread, median of {} interleaved\n",
             argv[1], g.triangles.size(), (mesh.positions.size() - 1) / 3, 3 * g.triangles.size(), rays.size(),
             hit_count, repeats);
  fmt::print("bench   (EmbreeReference::intersect1)       {:8.2f} Mrays/s\n", mrays / mb);
  fmt::print("user    (fields filled per call, welded)    {:8.2f} Mrays/s\n", mrays / mw);
  fmt::print("plain   (rtcIntersect1 loop, welded mesh)   {:8.2f} Mrays/s\n", mrays / mp);
  fmt::print("soup    (rtcIntersect1 loop, unshared)      {:8.2f} Mrays/s\n", mrays / ms);
  fmt::print("ours    (raylab bvh, intersect)             {:8.2f} Mrays/s\n", mrays / mo);
  fmt::print("ours / bench {:.3f}, ours / user {:.3f}, ours / plain {:.3f}\n", mb / mo, mw / mo, mp / mo);
  fmt::print("plain / bench {:.3f}, user / bench {:.3f}; rays answered otherwise than the bench: plain {}, user {}\n",
             mb / mp, mb / mw, differ, differ_welded);
  rtcReleaseScene(welded);
  rtcReleaseScene(unwelded);
  rtcReleaseDevice(device);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const raylab::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
