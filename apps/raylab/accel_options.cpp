#include "accel_options.h"

#include "raylab/accel/factory.h"

namespace raylab::cli {

void add_accel_parameter_options(CLI::App& cmd, AccelArgs& args) {
  SceneAccelOptions& o = args.options;
  cmd.add_option("--grid-density", o.config.grid.density,
                 "Uniform grid: cells per primitive (resolution rule in docs/accelerators.md)")
      ->check(CLI::Range(1e-3, 1e3))
      ->capture_default_str();
  cmd.add_option("--grid2-top-density", o.config.grid2.top_density,
                 "Two-level grid: top cells per N^0.6 for N primitives (docs/accelerators.md)")
      ->check(CLI::Range(1e-3, 1e3))
      ->capture_default_str();
  cmd.add_option("--grid2-leaf-density", o.config.grid2.leaf_density,
                 "Two-level grid: cells per primitive in each top cell's leaf grid")
      ->check(CLI::Range(1e-3, 1e3))
      ->capture_default_str();
  cmd.add_option("--octree-max-items", o.config.octree.max_items, "Octree: a cell with more primitives is split (K)")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd.add_option("--octree-max-depth", o.config.octree.max_depth, "Octree: deepest level of subdivision (L)")
      ->check(CLI::Range(0, 20))
      ->capture_default_str();
  cmd.add_flag("--bvh-spatial-splits", o.config.bvh.spatial_splits,
               "BVH (bvh, bvh2, bvh4, bvh8, bvh16): also consider spatial splits (SBVH): triangles may be clipped "
               "into several leaves; a lower SAH cost for a slower build");
  cmd.add_option("--wrap", args.wrap, "Bounding volume around each mesh and instance: none, box or sphere")
      ->check(CLI::IsMember({"none", "box", "sphere"}))
      ->capture_default_str();
  cmd.add_option("--bottom-accel", o.bottom,
                 "Structure inside each wrapped mesh and instance (default: the same as the top level)")
      ->check(CLI::IsMember(accelerator_choices()));
}

std::vector<std::string> accelerator_choices() {
  std::vector<std::string> names;
  for (auto n : accelerator_names()) names.emplace_back(n);
  return names;
}

}  // namespace raylab::cli
