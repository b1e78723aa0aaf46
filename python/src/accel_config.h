#pragma once
// `scene.build(accel, **config)`: keyword arguments to an AccelConfig (internal to the module).

#include <pybind11/pybind11.h>

#include <string>

#include "raylab/accel/factory.h"

namespace raylab::python {

/// The configuration of structure `accel` from keyword arguments named as the fields of
/// BvhConfig (bvh, bvh2, bvh4, bvh8, bvh16), GridConfig (grid) or OctreeConfig (octree). Raises
/// TypeError for a keyword the structure does not take, listing those it does, and for a value
/// of the wrong type.
AccelConfig accel_config(const std::string& accel, const pybind11::kwargs& config);

}  // namespace raylab::python
