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
  IrregularGridConfig& irr = o.config.irregular;
  cmd.add_option("--irregular-top-density", irr.top_density, "Irregular grid: top cells per primitive (lambda 1)")
      ->check(CLI::Range(1e-4, 1e3))
      ->capture_default_str();
  cmd.add_option("--irregular-sub-density", irr.sub_density,
                 "Irregular grid: cells per reference when a top cell is subdivided (lambda 2)")
      ->check(CLI::Range(1e-4, 1e3))
      ->capture_default_str();
  cmd.add_option("--irregular-max-shift", irr.max_shift,
                 "Irregular grid: most levels one subdivision step takes (2^s cells per axis)")
      ->check(CLI::Range(1, 6))
      ->capture_default_str();
  cmd.add_option("--irregular-max-depth", irr.max_depth,
                 "Irregular grid: most levels of subdivision below a top cell in all (0: the top grid only)")
      ->check(CLI::Range(0, 16))
      ->capture_default_str();
  cmd.add_option("--irregular-step-cost", irr.step_cost, "Irregular grid: merge cost of crossing a cell (C_step)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd.add_option("--irregular-prim-cost", irr.prim_cost, "Irregular grid: merge cost of a primitive test (C_prim)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd.add_option("--irregular-merge-rounds", irr.merge_rounds,
                 "Irregular grid: most rounds of x, y, z merge passes (0: no merging)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  cmd.add_option("--irregular-expand-rounds", irr.expand_rounds,
                 "Irregular grid: rounds of growing each cell's exit box over its six faces (0: no expansion)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  cmd.add_option("--irregular-mailbox", irr.mailbox,
                 "Irregular grid: test a primitive spanning several cells once per ray (true or false)")
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
