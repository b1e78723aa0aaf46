#pragma once
/// \file
/// Normal and bump maps: the one rule by which a material's maps tilt the shading normal.

#include "raylab/geometry/shading.h"
#include "raylab/scene/material.h"

namespace raylab {

/// The unit shading normal that `maps` give at surface coordinates (u, v) to a surface whose
/// untilted unit normal is `n` and whose tangents are `tangents` (all in one space; `n` on the
/// side the shape's own normal points to). The normal map, when there is one, is read in the
/// frame (t, b, n): t is dp/du made orthogonal to n, b = n x t turned towards dp/dv. Otherwise the
/// bump map's height h displaces the surface by h n, and the normal is that of the displaced
/// surface, (dp/du + dh/du n) x (dp/dv + dh/dv n), with the derivatives of h taken across one
/// texel. Without either map, or where the frame is degenerate, returns `n`.
Vec3 mapped_normal(const MaterialMaps& maps, Vec3 n, const SurfaceTangents& tangents, float u, float v);

/// Tilts `si.shading_normal` by the normal or bump map of `maps` (mapped_normal), keeping it on
/// the side of si.geometric_normal that the ray arrived from: a map cannot turn a surface away
/// from the viewer, which would leave it black or lit from behind.
void apply_normal_maps(const MaterialMaps& maps, const SurfaceTangents& tangents, SurfaceInteraction& si);

/// True when `image` (read as linear data) holds tangent-space normals rather than heights:
/// its texels are, on average, close to the untilted normal (0.5, 0.5, 1) and coloured, where a
/// height map is grey. The OBJ loader asks, because exporters write either kind as map_Bump.
bool looks_like_normal_map(const TextureImage& image);

}  // namespace raylab
