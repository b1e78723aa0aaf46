#include "accel_config.h"

#include <functional>
#include <map>

namespace raylab::python {

namespace py = pybind11;

namespace {

// Setters by keyword for one kind of structure.
using Setters = std::map<std::string, std::function<void(AccelConfig&, py::handle)>>;

template <class T>
std::function<void(AccelConfig&, py::handle)> setter(T AccelConfig::*part, auto field) {
  return [part, field](AccelConfig& c, py::handle v) {
    using Value = std::remove_reference_t<decltype((c.*part).*field)>;
    if constexpr (std::is_same_v<Value, bool>) {
      if (!py::isinstance<py::bool_>(v)) throw py::type_error("expected True or False");
    }
    (c.*part).*field = v.cast<Value>();
  };
}

Setters bvh_setters() {
  return {{"bin_count", setter(&AccelConfig::bvh, &BvhConfig::bin_count)},
          {"max_leaf_size", setter(&AccelConfig::bvh, &BvhConfig::max_leaf_size)},
          {"traversal_cost", setter(&AccelConfig::bvh, &BvhConfig::traversal_cost)},
          {"intersection_cost", setter(&AccelConfig::bvh, &BvhConfig::intersection_cost)},
          {"spatial_splits", setter(&AccelConfig::bvh, &BvhConfig::spatial_splits)},
          {"spatial_split_alpha", setter(&AccelConfig::bvh, &BvhConfig::spatial_split_alpha)},
          {"spatial_split_budget", setter(&AccelConfig::bvh, &BvhConfig::spatial_split_budget)}};
}

Setters setters_of(const std::string& accel) {
  if (accel.rfind("bvh", 0) == 0) return bvh_setters();
  if (accel == "grid") {
    return {{"density", setter(&AccelConfig::grid, &GridConfig::density)},
            {"mailbox", setter(&AccelConfig::grid, &GridConfig::mailbox)}};
  }
  if (accel == "grid2") {
    return {{"top_density", setter(&AccelConfig::grid2, &TwoLevelGridConfig::top_density)},
            {"leaf_density", setter(&AccelConfig::grid2, &TwoLevelGridConfig::leaf_density)},
            {"mailbox", setter(&AccelConfig::grid2, &TwoLevelGridConfig::mailbox)}};
  }
  if (accel == "octree") {
    return {{"max_items", setter(&AccelConfig::octree, &OctreeConfig::max_items)},
            {"max_depth", setter(&AccelConfig::octree, &OctreeConfig::max_depth)},
            {"mailbox", setter(&AccelConfig::octree, &OctreeConfig::mailbox)}};
  }
  if (accel == "irregular") {
    return {{"top_density", setter(&AccelConfig::irregular, &IrregularGridConfig::top_density)},
            {"sub_density", setter(&AccelConfig::irregular, &IrregularGridConfig::sub_density)},
            {"max_shift", setter(&AccelConfig::irregular, &IrregularGridConfig::max_shift)},
            {"max_depth", setter(&AccelConfig::irregular, &IrregularGridConfig::max_depth)},
            {"step_cost", setter(&AccelConfig::irregular, &IrregularGridConfig::step_cost)},
            {"prim_cost", setter(&AccelConfig::irregular, &IrregularGridConfig::prim_cost)},
            {"merge_rounds", setter(&AccelConfig::irregular, &IrregularGridConfig::merge_rounds)},
            {"expand_rounds", setter(&AccelConfig::irregular, &IrregularGridConfig::expand_rounds)},
            {"mailbox", setter(&AccelConfig::irregular, &IrregularGridConfig::mailbox)}};
  }
  return {};
}

}  // namespace

AccelConfig accel_config(const std::string& accel, const py::kwargs& config) {
  AccelConfig result;
  const Setters setters = setters_of(accel);
  for (const auto& [key, value] : config) {
    const std::string name = py::str(key);
    const auto it = setters.find(name);
    if (it == setters.end()) {
      std::string valid;
      for (const auto& s : setters) valid += (valid.empty() ? "" : ", ") + s.first;
      throw py::type_error("build(): accel '" + accel + "' takes no parameter '" + name + "'" +
                           (valid.empty() ? std::string(" (it takes none)") : "; it takes: " + valid));
    }
    try {
      it->second(result, value);
    } catch (const py::cast_error&) {
      throw py::type_error("build(): parameter '" + name + "' cannot be " + std::string(py::repr(value)));
    } catch (const py::type_error& e) {
      throw py::type_error("build(): parameter '" + name + "': " + e.what());
    }
  }
  return result;
}

}  // namespace raylab::python
