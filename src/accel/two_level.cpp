#include "raylab/accel/two_level.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <vector>

#include "raylab/core/stopwatch.h"

namespace raylab {

namespace {

// Where a counted query sends the work done inside groups. The top level reaches a group through
// Geometry's type-erased callback, which has no room for a statistics record, so the counted
// entry points park it here for the duration of the query (per thread, so queries on other
// threads are unaffected).
thread_local TraversalStats* t_count_sink = nullptr;

// One top-level item: a wrapped mesh of the flat geometry (global ids already), or an instance
// (prototype ids, shifted by `id_base` on the way out).
struct Group {
  const Accelerator* accel = nullptr;
  BoundingWrapper wrapper;  // world space
  const Instance* instance = nullptr;
  std::uint32_t id_base = 0;
};

// The wrapper test a ray pays before entering the group's own structure.
bool enters_wrapper(const Group& g, const Ray& ray) {
  if (t_count_sink != nullptr) {
    // The top level counted this item as a primitive test; it is a bounding-volume test, or,
    // unwrapped, no test at all (the ray goes straight into the instance's structure).
    --t_count_sink->prim_tests;
    if (g.wrapper.mode != WrapMode::kNone) ++t_count_sink->volume_tests;
  }
  return g.wrapper.admits(ray);
}

Ray to_local(const Instance& inst, const Ray& ray) {
  Ray local = ray;
  // The direction is mapped without normalising, so t names the same point in both spaces.
  local.origin = inst.to_local.point(ray.origin);
  local.direction = inst.to_local.vector(ray.direction);
  return local;
}

// Adds a sub-structure's traversal work to the sink; its `hits` stay out, since the query that
// reached the group counts its own.
void add_inner_work(const TraversalStats& inner) {
  t_count_sink->nodes_visited += inner.nodes_visited;
  t_count_sink->prim_tests += inner.prim_tests;
  t_count_sink->volume_tests += inner.volume_tests;
}

bool sub_intersect(const Accelerator& accel, Ray& ray, Hit& hit) {
  if (t_count_sink == nullptr) return accel.intersect(ray, hit);
  TraversalStats inner;
  const bool found = accel.intersect_counted(ray, hit, inner);
  add_inner_work(inner);
  return found;
}

bool sub_occluded(const Accelerator& accel, const Ray& ray) {
  if (t_count_sink == nullptr) return accel.occluded(ray);
  TraversalStats inner;
  const bool found = accel.occluded_counted(ray, inner);
  add_inner_work(inner);
  return found;
}

bool group_intersect(const void* context, Ray& ray, Hit& hit) {
  const Group& g = *static_cast<const Group*>(context);
  if (!enters_wrapper(g, ray)) return false;
  if (g.instance == nullptr) return sub_intersect(*g.accel, ray, hit);  // global ids: ties resolve inside
  // An instance numbers its primitives from 0. Equal-distance ties with the current hit go to the
  // lower global id: when this instance's ids can be lower, let a hit at exactly ray.tmax through,
  // then keep it only if its global id is lower.
  Ray local = to_local(*g.instance, ray);
  local.tmax = hit.tie_limit(g.id_base, ray.tmax);
  Hit local_hit;
  if (!sub_intersect(*g.accel, local, local_hit)) return false;
  const std::uint32_t id = g.id_base + local_hit.prim_id;
  if (local_hit.t >= ray.tmax && hit.valid() && id > hit.prim_id) return false;
  ray.tmax = local_hit.t;
  hit = {local_hit.t, id, local_hit.u, local_hit.v};
  return true;
}

bool group_occluded(const void* context, const Ray& ray) {
  const Group& g = *static_cast<const Group*>(context);
  if (!enters_wrapper(g, ray)) return false;
  return sub_occluded(*g.accel, g.instance == nullptr ? ray : to_local(*g.instance, ray));
}

Geometry copy_shapes(const Geometry& g) {
  Geometry out;
  out.triangles = g.triangles;
  out.spheres = g.spheres;
  out.cylinders = g.cylinders;
  out.disks = g.disks;
  out.quads = g.quads;
  return out;
}

template <class T>
std::size_t bytes_of(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

// The two-level structure itself.
class TwoLevel final : public Accelerator {
 public:
  TwoLevel(const Geometry& flat, std::span<const Geometry> prototypes, std::span<const Instance> instances,
           const SceneAccelOptions& options)
      : m_options(options), m_top(copy_shapes(flat)) {
    const auto start = std::chrono::steady_clock::now();
    if (m_options.bottom.empty()) m_options.bottom = m_options.top;
    const std::string& bottom = m_options.bottom;
    std::vector<std::uint32_t> top_ids;

    // Meshes of the flat geometry: objects with enough primitives, when wrapping.
    std::vector<std::vector<std::uint32_t>> meshes;
    if (m_options.wrap == WrapMode::kNone) {
      top_ids = flat.primitive_ids();
    } else {
      std::map<std::uint32_t, std::vector<std::uint32_t>> by_object;
      for (std::uint32_t id = 0; id < flat.size(); ++id) by_object[flat.object_of(id)].push_back(id);
      for (auto& [object, ids] : by_object) {
        if (ids.size() >= m_options.min_mesh_size) {
          meshes.push_back(std::move(ids));
        } else {
          top_ids.insert(top_ids.end(), ids.begin(), ids.end());
        }
      }
      std::sort(top_ids.begin(), top_ids.end());
    }
    m_groups.reserve(meshes.size() + instances.size());  // the shapes point into it: no reallocation
    for (const auto& ids : meshes) {
      m_bottoms.push_back(make_accelerator(bottom, m_top, ids, m_options.config));
      Group g;
      g.accel = m_bottoms.back().get();
      g.wrapper.mode = m_options.wrap;
      g.wrapper.box = g.accel->bounds();
      std::vector<Vec3> points;
      for (std::uint32_t id : ids) append_hull_points(m_top, id, points);
      g.wrapper.sphere = sphere_around(points);
      m_groups.push_back(g);
    }

    // Prototypes: one structure each, shared by all of its instances.
    std::vector<const Accelerator*> prototype_accel(prototypes.size(), nullptr);
    std::vector<Sphere> prototype_sphere(prototypes.size());
    for (const Instance& inst : instances) {
      const std::uint32_t p = inst.prototype;
      if (prototype_accel[p] != nullptr) continue;
      m_bottoms.push_back(make_accelerator(bottom, prototypes[p], m_options.config));
      prototype_accel[p] = m_bottoms.back().get();
    }
    for (const Instance& inst : instances) {
      const Geometry& proto = prototypes[inst.prototype];
      if (proto.size() == 0) continue;
      Group g;
      g.accel = prototype_accel[inst.prototype];
      // Without wrapping the instance is still one item (its geometry lives in its own space), but
      // a ray enters it without a bounding-volume test of its own.
      g.wrapper.mode = m_options.wrap;
      g.instance = &inst;
      g.id_base = flat.size() + inst.first_prim_offset;
      std::vector<Vec3> points;
      for (std::uint32_t id = 0; id < proto.size(); ++id) append_hull_points(proto, id, points);
      for (Vec3& p : points) p = inst.to_world.point(p);
      for (Vec3 p : points) g.wrapper.box.extend(p);
      g.wrapper.sphere = sphere_around(points);
      m_groups.push_back(g);
    }
    for (std::size_t i = 0; i < m_groups.size(); ++i) {
      GroupShape shape;
      shape.box = m_groups[i].wrapper.box;
      if (m_options.wrap == WrapMode::kSphere) shape.sphere = m_groups[i].wrapper.sphere;
      shape.context = &m_groups[i];
      shape.intersect = group_intersect;
      shape.occluded = group_occluded;
      m_top.groups.push_back(shape);
      top_ids.push_back(kGroupIdBase + static_cast<std::uint32_t>(i));
    }
    m_top_accel = make_accelerator(m_options.top, m_top, top_ids, m_options.config);
    m_primitive_count = flat.size();
    for (const Instance& inst : instances) m_primitive_count += prototypes[inst.prototype].size();
    m_build_seconds = seconds_since(start);
  }

  Box3 bounds() const override { return m_top_accel->bounds(); }
  bool intersect(Ray& ray, Hit& hit) const override { return m_top_accel->intersect(ray, hit); }
  bool occluded(const Ray& ray) const override { return m_top_accel->occluded(ray); }

  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const override {
    TraversalStats* outer = t_count_sink;
    t_count_sink = &stats;
    const bool found = m_top_accel->intersect_counted(ray, hit, stats);
    t_count_sink = outer;
    return found;
  }

  bool occluded_counted(const Ray& ray, TraversalStats& stats) const override {
    TraversalStats* outer = t_count_sink;
    t_count_sink = &stats;
    const bool found = m_top_accel->occluded_counted(ray, stats);
    t_count_sink = outer;
    return found;
  }

  AccelInfo info() const override {
    AccelInfo info = m_top_accel->info();
    info.name = m_options.top;
    if (m_options.bottom != m_options.top) info.name += "/" + m_options.bottom;
    info.name += " (wrap " + std::string(wrap_mode_name(m_options.wrap)) + ")";
    info.build_seconds = m_build_seconds;
    info.memory_bytes += bytes_of(m_top.triangles) + bytes_of(m_top.spheres) + bytes_of(m_top.cylinders) +
                         bytes_of(m_top.disks) + bytes_of(m_top.quads) + bytes_of(m_top.groups) + bytes_of(m_groups);
    int deepest_bottom = 0;
    for (const auto& b : m_bottoms) {
      const AccelInfo bi = b->info();
      info.memory_bytes += bi.memory_bytes;
      info.node_count += bi.node_count;
      info.leaf_count += bi.leaf_count;
      deepest_bottom = std::max(deepest_bottom, bi.max_depth);
    }
    info.max_depth += deepest_bottom;
    info.primitive_count = m_primitive_count;
    return info;
  }

 private:
  SceneAccelOptions m_options;
  Geometry m_top;  // the flat shapes (same ids) plus one group per mesh and instance
  std::vector<Group> m_groups;
  std::vector<std::unique_ptr<Accelerator>> m_bottoms;
  std::unique_ptr<Accelerator> m_top_accel;
  std::size_t m_primitive_count = 0;
  double m_build_seconds = 0.0;
};

}  // namespace

std::unique_ptr<Accelerator> make_scene_accelerator(const Geometry& flat, std::span<const Geometry> prototypes,
                                                    std::span<const Instance> instances,
                                                    const SceneAccelOptions& options) {
  if (instances.empty() && options.wrap == WrapMode::kNone) return make_accelerator(options.top, flat, options.config);
  return std::make_unique<TwoLevel>(flat, prototypes, instances, options);
}

}  // namespace raylab
