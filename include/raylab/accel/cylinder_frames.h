#pragma once
/// \file
/// The precomputed frames of the cylinders a structure holds (raylab/geometry/cylinder.h): what
/// the cylinder test needs that does not depend on the ray, computed once when the structure is
/// built instead of at every test. Every structure that tests cylinders itself keeps one.

#include <cstdint>
#include <span>
#include <vector>

#include "raylab/geometry/cylinder.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// The frames of the cylinders among a structure's primitive ids, one per id of the range those
/// ids span (whether the structure holds it or not): a structure over one object's primitives
/// computes only that object's, and finding a frame is a subtraction and a comparison.
struct CylinderFrames {
  std::vector<CylinderFrame> frames;  ///< the frame of cylinder id `begin + i` at i
  std::uint32_t begin = 0;            ///< the id of frames[0]

  /// The frames of the cylinders of `geometry` among `ids` (global primitive ids).
  static CylinderFrames of(const Geometry& geometry, std::span<const std::uint32_t> ids);

  /// The frame of primitive `id` when it is a cylinder of the range, else null.
  const CylinderFrame* find(std::uint32_t id) const {
    const std::uint32_t i = id - begin;  // wraps around below the range
    return i < frames.size() ? &frames[i] : nullptr;
  }

  /// The bytes the frames take.
  std::size_t bytes() const { return frames.size() * sizeof(CylinderFrame); }
};

}  // namespace raylab
