#include "mesh_arrays.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace raylab {

namespace {

template <class Real>
Geometry geometry_from(std::span<const Real> vertices, std::span<const std::uint32_t> indices) {
  if (vertices.size() % 3 != 0) {
    throw std::invalid_argument("vertices: expected 3 coordinates per vertex, got " + std::to_string(vertices.size()) +
                                " numbers");
  }
  if (indices.size() % 3 != 0) {
    throw std::invalid_argument("indices: expected 3 vertex indices per triangle, got " +
                                std::to_string(indices.size()) + " numbers");
  }
  const std::size_t vertex_count = vertices.size() / 3;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    // Rounding to float can overflow a finite double, which would be just as bad.
    if (!std::isfinite(static_cast<float>(vertices[i]))) {
      throw std::invalid_argument("vertices: vertex " + std::to_string(i / 3) + " has a coordinate that is not a " +
                                  "finite float (" + std::to_string(static_cast<double>(vertices[i])) + ")");
    }
  }
  Geometry geometry;
  geometry.triangles.reserve(indices.size() / 3);
  geometry.triangle_objects.reserve(indices.size() / 3);
  auto vertex = [&](std::uint32_t v) {
    const std::size_t at = std::size_t{v} * 3;
    return Vec3{static_cast<float>(vertices[at]), static_cast<float>(vertices[at + 1]),
                static_cast<float>(vertices[at + 2])};
  };
  for (std::size_t t = 0; t < indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (indices[t + k] >= vertex_count) {
        throw std::invalid_argument("indices: triangle " + std::to_string(t / 3) + " refers to vertex " +
                                    std::to_string(indices[t + k]) + ", but there are " + std::to_string(vertex_count) +
                                    " vertices");
      }
    }
    geometry.add(Triangle{vertex(indices[t]), vertex(indices[t + 1]), vertex(indices[t + 2])}, 0);
  }
  return geometry;
}

}  // namespace

Geometry geometry_from_arrays(std::span<const float> vertices, std::span<const std::uint32_t> indices) {
  return geometry_from(vertices, indices);
}

Geometry geometry_from_arrays(std::span<const double> vertices, std::span<const std::uint32_t> indices) {
  return geometry_from(vertices, indices);
}

}  // namespace raylab
