// cast_rays: builds a ray-query structure over a mesh with the raylab library and shoots a grid
// of parallel rays at it.
//
//   cast_rays [MESH [N]]
//
// MESH is a mesh or scene file (.obj, .ply, .stl, .off, .gltf, .glb, .json, .nff) or a built-in
// scene name ("demo"); without one, a quad of two triangles built here. N x N rays (default 256)
// start on a plane one unit in front of the mesh's bounding box (on its +z side) and travel
// along -z, one through the centre of each cell of a grid over the box's x-y extent: an
// orthographic view. The program prints how many rays hit, at what distance, and how many
// different triangles they found.

#include <raylab/core/error.h>
#include <raylab/io/scene_loader.h>
#include <raylab/query/ray_query.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <vector>

namespace {

// The quad [-1, 1] x [-1, 1] at z = 0 as two triangles: flat arrays of x, y, z per vertex and
// three vertex indices per triangle, the form of a mesh held by another program.
raylab::RayQuery built_in_quad() {
  const std::vector<float> vertices = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
  return raylab::RayQuery::from_triangles(vertices, indices);
}

// The N x N rays, six floats each (origin x, y, z, then direction x, y, z): one array, which a
// RayBatch reads in place with strides of 6.
std::vector<float> grid_of_rays(const raylab::Box3& box, int n) {
  std::vector<float> rays;
  rays.reserve(std::size_t(n) * n * 6);
  const float start_z = box.hi.z + 1.f;
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const float x = box.lo.x + (box.hi.x - box.lo.x) * (float(col) + 0.5f) / float(n);
      const float y = box.lo.y + (box.hi.y - box.lo.y) * (float(row) + 0.5f) / float(n);
      rays.insert(rays.end(), {x, y, start_z, 0.f, 0.f, -1.f});
    }
  }
  return rays;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 3) {
    std::fprintf(stderr, "usage: cast_rays [MESH [N]]\n");
    return 2;
  }
  const int n = argc == 3 ? std::atoi(argv[2]) : 256;
  if (n < 1 || n > 8192) {
    std::fprintf(stderr, "cast_rays: N must be a whole number from 1 to 8192\n");
    return 2;
  }
  try {
    // A RayQuery owns its primitives: copied from the caller's arrays, or taken from a loaded
    // scene (whose instances are baked into copies, so that every primitive has one id).
    raylab::RayQuery query = argc > 1 ? raylab::RayQuery::from_scene(raylab::load_scene(argv[1])) : built_in_quad();
    // Any name of raylab::accelerator_names() works here ("grid", "octree", "brute", ...); the
    // answers are the same, only the time differs.
    query.build("bvh");

    const raylab::Box3 box = query.geometry().bounds();
    if (box.empty()) {
      std::fprintf(stderr, "cast_rays: %s has no primitives\n", argc > 1 ? argv[1] : "the quad");
      return 1;
    }
    const std::vector<float> rays = grid_of_rays(box, n);
    const std::size_t count = rays.size() / 6;

    raylab::RayBatch batch;
    batch.count = count;
    batch.origins = rays.data();
    batch.directions = rays.data() + 3;
    batch.origin_stride = batch.direction_stride = 6;

    // Answers go straight into our arrays; the ones we do not ask for (uv, normal, object id)
    // stay null and are not written.
    std::vector<float> t(count);
    std::vector<std::int32_t> prim(count);
    raylab::HitArrays hits;
    hits.t = t.data();
    hits.prim_id = prim.data();
    // All cores; the answers do not depend on the thread count.
    query.intersect(batch, hits);

    std::size_t hit_count = 0;
    double t_sum = 0.0;
    float t_min = std::numeric_limits<float>::infinity(), t_max = 0.f;
    std::vector<std::int32_t> hit_triangles;
    for (std::size_t i = 0; i < count; ++i) {
      if (prim[i] < 0) continue;  // a miss: prim_id -1 and t = +inf
      ++hit_count;
      t_sum += t[i];
      t_min = std::min(t_min, t[i]);
      t_max = std::max(t_max, t[i]);
      hit_triangles.push_back(prim[i]);
    }
    std::sort(hit_triangles.begin(), hit_triangles.end());
    const auto distinct = std::unique(hit_triangles.begin(), hit_triangles.end()) - hit_triangles.begin();

    std::printf("rays:                    %zu (%d x %d along -z)\n", count, n, n);
    std::printf("hits:                    %zu of %zu (%.2f%%)\n", hit_count, count,
                100.0 * double(hit_count) / double(count));
    if (hit_count > 0) {
      std::printf("t min/mean/max:          %g / %g / %g\n", t_min, t_sum / double(hit_count), t_max);
    }
    std::printf("distinct primitives hit: %td of %u\n", distinct, query.geometry().size());
    return 0;
  } catch (const raylab::UsageError& e) {
    std::fprintf(stderr, "cast_rays: %s\n", e.what());
    return 2;
  } catch (const raylab::InputError& e) {  // a bad file, with file:line:col where there is one
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cast_rays: %s\n", e.what());
    return 1;
  }
}
