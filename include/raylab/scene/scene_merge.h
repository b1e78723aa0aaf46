#pragma once
/// \file
/// Placing one scene's contents into another under a transform: meshes from files, instances
/// and SPD generators in scene files all arrive this way.

#include <cstdint>
#include <optional>

#include "raylab/core/transform.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Scale factor of `t` when it is a similarity (rotation, uniform scale, translation, possibly a
/// mirror), else nothing. Spheres, cylinders and disks stay analytic only under similarities.
std::optional<double> similarity_scale(const Transform& t);

/// Appends the geometry of `src` to `dst`, transformed by `placement`, with `src`'s objects and
/// materials copied (their ids remapped), or, when `material` is given, every object of `src`
/// using that material of `dst`. Lights, camera and settings of `src` are not copied. Throws
/// UsageError when `src` has spheres, cylinders or disks and `placement` is not a similarity
/// (they would stop being spheres), or when `placement` is not invertible.
void append_scene(Scene& dst, const Scene& src, const Transform& placement,
                  std::optional<std::uint32_t> material = std::nullopt);

/// Replaces every instance by a transformed copy of its prototype in `scene.geometry` (for
/// writers, which know nothing of instancing). Throws UsageError when an instance's transform is
/// not a similarity and its prototype has spheres, cylinders or disks.
void bake_instances(Scene& scene);

}  // namespace raylab
