#pragma once
/// \file
/// Which way is up in a mesh that does not say: scanned objects and 3D-printing parts are cut
/// flat where they stood, so a large flat face at one end of the bounds, facing along an axis,
/// is their base. Meshes without such a base keep +Y, the convention of OBJ, PLY and glTF.

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "raylab/core/vec3.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// The six axis directions an up axis may take, in the order detection prefers them on a tie:
/// +Y (the formats' convention), +Z (scanners' and CAD's), +X, then the negative ones.
inline constexpr std::array<Vec3, 6> kUpAxes{Vec3{0.f, 1.f, 0.f},  Vec3{0.f, 0.f, 1.f},  Vec3{1.f, 0.f, 0.f},
                                             Vec3{0.f, -1.f, 0.f}, Vec3{0.f, 0.f, -1.f}, Vec3{-1.f, 0.f, 0.f}};

/// For each of kUpAxes, how much of a flat base the mesh has below it: the area of the
/// triangles facing along that axis (within 5 degrees, either winding) that lie at the bounds'
/// lowest end along it (within 1% of the extent), over the area of the bounds' cross-section
/// there. 1 for a box; 0 where nothing is flat at that end. Flat triangles only (not instances).
std::array<float, 6> flat_base_fractions(const Scene& scene);

/// The smallest flat_base_fractions() value that counts as a base. Measured on the scans in
/// ../shared/scenes: nefertiti.obj's cut base 0.25 (+Z); the bunny's flat patches 0.059 (+Y, where it sits), the
/// armadillo's feet 0.014, igea.ply 0.001 (+Y by the fallback).
inline constexpr float kMinBaseFraction = 0.1f;

/// The up axis the mesh's flat base shows: of the axes whose fraction reaches kMinBaseFraction,
/// the first in kUpAxes order among those within 90% of the largest; empty when none does (the
/// caller keeps +Y).
std::optional<Vec3> detect_up_axis(const Scene& scene);

/// The axis a name gives: "x", "y", "z", "-x", "-y", "-z" (also with "+", any case); empty
/// for anything else.
std::optional<Vec3> parse_up_axis(std::string_view name);

/// The name of one of kUpAxes ("z", "-y").
std::string up_axis_name(Vec3 axis);

}  // namespace raylab
