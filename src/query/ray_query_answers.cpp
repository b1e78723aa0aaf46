// The batched queries of RayQuery: each chunk of rays is gathered from the caller's arrays,
// traced (as packets when the chunk is coherent) and its answers written back in place.

#include <cmath>
#include <limits>
#include <vector>

#include "batch_runner.h"
#include "ray_query_state.h"
#include "raylab/geometry/shading.h"
#include "raylab/query/ray_query.h"

namespace raylab {

namespace {

// A chunk is traced as packets when its rays come in runs of one direction octant at least this
// long on average: camera rays in scanline order do, bounce rays do not. Packets of scattered
// rays only add work over single rays.
constexpr std::size_t kCoherentRun = 8;

// The rays [begin, end) of `batch`, gathered into `rays`. The common case, one tmin and tmax
// for all, reads only the two rows of three floats per ray.
void gather(const RayBatch& batch, std::size_t begin, std::size_t end, std::vector<Ray>& rays) {
  rays.resize(end - begin);
  if (batch.tmins != nullptr || batch.tmaxs != nullptr) {
    for (std::size_t i = begin; i < end; ++i) rays[i - begin] = batch.ray(i);
    return;
  }
  const float* o = batch.origins + static_cast<std::ptrdiff_t>(begin) * batch.origin_stride;
  const float* d = batch.directions + static_cast<std::ptrdiff_t>(begin) * batch.direction_stride;
  for (Ray& r : rays) {
    r.origin = {o[0], o[1], o[2]};
    r.direction = {d[0], d[1], d[2]};
    r.tmin = batch.tmin;
    r.tmax = batch.tmax;
    o += batch.origin_stride;
    d += batch.direction_stride;
  }
}

// Whether `rays` are worth tracing as packets (see kCoherentRun).
bool coherent(const std::vector<Ray>& rays) {
  std::size_t runs = 1;
  int previous = rays.empty() ? 0 : direction_octant(rays[0].direction);
  for (const Ray& r : rays) {
    const int octant = direction_octant(r.direction);
    runs += octant != previous ? 1 : 0;
    previous = octant;
  }
  return rays.size() >= runs * kCoherentRun;
}

// The unit geometric normal of primitive `hit.prim_id` as the primitive is wound, whichever
// side the ray came from. Triangles need only their vertices; other shapes ask surface_at with
// the ray as the caller gave it (`ray_of()`).
template <class RayOf>
Vec3 wound_normal(const Geometry& geometry, const Hit& hit, const RayOf& ray_of) {
  if (hit.prim_id < geometry.triangles.size()) return normalize(triangle_normal(geometry.triangles[hit.prim_id]));
  const SurfaceInteraction s = surface_at(geometry, ray_of(), hit);
  return s.front_face ? s.geometric_normal : -s.geometric_normal;
}

// Writes the answer of ray `i` of `rays` to `out`.
void write_hit(const Geometry& geometry, const RayBatch& rays, const Hit& hit, std::size_t i, const HitArrays& out) {
  const bool found = hit.valid();
  if (out.t != nullptr) out.t[i] = found ? hit.t : std::numeric_limits<float>::infinity();
  if (out.prim_id != nullptr) out.prim_id[i] = found ? static_cast<std::int32_t>(hit.prim_id) : -1;
  if (out.object_id != nullptr) {
    const bool triangle = hit.prim_id < geometry.triangle_objects.size();
    out.object_id[i] = !found     ? -1
                       : triangle ? static_cast<std::int32_t>(geometry.triangle_objects[hit.prim_id])
                                  : static_cast<std::int32_t>(geometry.object_of(hit.prim_id));
  }
  if (out.uv != nullptr) {
    out.uv[2 * i] = found ? hit.u : 0.f;
    out.uv[2 * i + 1] = found ? hit.v : 0.f;
  }
  if (out.normal != nullptr) {
    const Vec3 n = found ? wound_normal(geometry, hit, [&] { return rays.ray(i); }) : Vec3{};
    for (int a = 0; a < 3; ++a) out.normal[3 * i + static_cast<std::size_t>(a)] = n[a];
  }
}

// The number of primitives `ray` crosses, through `accel`'s all-hits walk; `scratch` is reused.
std::uint32_t count_crossings(const Accelerator& accel, const Ray& ray, std::vector<Hit>& scratch) {
  scratch.clear();
  accel.all_hits(ray, scratch);
  return static_cast<std::uint32_t>(scratch.size());
}

}  // namespace

void RayQuery::intersect(const RayBatch& rays, const HitArrays& out, const QueryOptions& options) const {
  const Accelerator& accel = accelerator();
  const Geometry& geometry = m_state->scene.geometry;
  run_query_batch(rays.count, options, [&](std::size_t begin, std::size_t end) {
    // Per thread, so that a chunk allocates nothing.
    thread_local std::vector<Ray> chunk;
    thread_local std::vector<Hit> hits;
    gather(rays, begin, end, chunk);
    hits.assign(chunk.size(), Hit{});
    if (coherent(chunk)) {
      accel.intersect(std::span<Ray>(chunk), std::span<Hit>(hits));
    } else {
      for (std::size_t i = 0; i < chunk.size(); ++i) accel.intersect(chunk[i], hits[i]);
    }
    for (std::size_t i = 0; i < chunk.size(); ++i) write_hit(geometry, rays, hits[i], begin + i, out);
  });
}

void RayQuery::occluded(const RayBatch& rays, std::uint8_t* occluded, const QueryOptions& options) const {
  const Accelerator& accel = accelerator();
  run_query_batch(rays.count, options, [&](std::size_t begin, std::size_t end) {
    thread_local std::vector<Ray> chunk;
    gather(rays, begin, end, chunk);
    if (coherent(chunk)) {
      accel.occluded(std::span<const Ray>(chunk), std::span<std::uint8_t>(occluded + begin, chunk.size()));
    } else {
      for (std::size_t i = 0; i < chunk.size(); ++i) occluded[begin + i] = accel.occluded(chunk[i]) ? 1 : 0;
    }
  });
}

void RayQuery::count_intersections(const RayBatch& rays, std::uint32_t* counts, const QueryOptions& options) const {
  const Accelerator& accel = accelerator();
  run_query_batch(rays.count, options, [&](std::size_t begin, std::size_t end) {
    thread_local std::vector<Hit> scratch;
    for (std::size_t i = begin; i < end; ++i) counts[i] = count_crossings(accel, rays.ray(i), scratch);
  });
}

void RayQuery::contains(const float* points, std::size_t count, std::ptrdiff_t stride, std::uint8_t* inside,
                        const QueryOptions& options) const {
  const Accelerator& accel = accelerator();
  // Any direction gives the parity for a closed surface; one with no zero component and no
  // simple ratio between components makes rays along faces and edges of axis-aligned models
  // (where the tie rule would decide every answer) rare.
  const Vec3 direction = normalize(Vec3{0.5773f, 0.6411f, 0.5059f});
  run_query_batch(count, options, [&](std::size_t begin, std::size_t end) {
    thread_local std::vector<Hit> scratch;
    for (std::size_t i = begin; i < end; ++i) {
      const float* p = points + static_cast<std::ptrdiff_t>(i) * stride;
      Ray ray;
      ray.origin = {p[0], p[1], p[2]};
      ray.direction = direction;
      inside[i] = count_crossings(accel, ray, scratch) % 2 == 1 ? 1 : 0;
    }
  });
}

}  // namespace raylab
