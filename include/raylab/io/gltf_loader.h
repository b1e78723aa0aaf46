#pragma once
/// \file
/// glTF 2.0 scenes (.gltf with its buffers and images, or a single .glb) through tinygltf, with
/// everything tinygltf leaves unchecked checked by raylab.

#include <string>

#include "raylab/core/transform.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// How load_gltf places the file and which files it may read.
struct GltfLoadOptions {
  /// Applied on top of the file's node transforms (world = placement x node's world transform),
  /// to the camera as well.
  Transform placement = Transform::identity();
  /// Follow buffer and image URIs that leave the folder of the glTF file (compared after `..`,
  /// %-escapes and symbolic links are resolved). Off by default: a file from elsewhere must not
  /// make raylab read arbitrary files. data: URIs are always fine.
  bool allow_outside_paths = false;
  /// Replace `scene.camera` by the file's first perspective camera (the first camera node met in
  /// scene order), and set `scene.camera_from_file`. Off by default: a model placed into another
  /// scene must not move that scene's camera.
  bool use_camera = false;
};

/// Appends the triangles of glTF 2.0 file `path` (.gltf or .glb, told apart by content) to
/// `scene`: the meshes of the default scene (or scene 0, or, with no scenes, of every root node),
/// each node's transform (matrix or translation/rotation/scale) composed parent x child.
///
/// Primitives of mode TRIANGLES (and TRIANGLE_STRIP / TRIANGLE_FAN, unrolled) are read, indexed
/// (u8, u16, u32 indices) or not, with POSITION, NORMAL (float vec3) and the texture coordinates
/// their material's base-colour texture names (float, or normalised u8/u16, vec2). Points and
/// lines have no area and are skipped with a warning. Each glTF material becomes one
/// raylab material and one object: baseColorFactor -> color, baseColorTexture (PNG or JPEG) ->
/// image texture, emissiveFactor -> emission, alphaMode BLEND -> transmittance = 1 - alpha, and
/// metallic/roughness mapped roughly onto the Phong/Whitted parameters (see gltf_loader.cpp).
/// Primitives without a material get raylab's default matte material.
///
/// Throws InputError naming the file and the element ("meshes[2].primitives[0]: index 812 out of
/// range (vertex count 500)") for anything invalid: indices of accessors, buffer views, buffers,
/// nodes, meshes, materials, textures, images or cameras out of range, accessor types or
/// component types that do not fit their use, data outside its buffer view or buffer, index
/// values past the vertex count, non-finite numbers, node cycles, a buffer or image URI outside
/// the folder (unless allowed) or missing, and malformed JSON or GLB containers. Files raylab
/// cannot read whatever their data are refused with the cause named (not a symptom of it): a
/// glTF 1.0 file (asset.version "1.0", a version 1 GLB, or top-level objects keyed by name where
/// glTF 2.0 has arrays), any other asset.version but 2.x, any extension in extensionsRequired
/// (raylab supports none: Draco, meshopt, quantisation, Basis textures, texture transforms change
/// what the data mean), and a Draco-compressed primitive without an uncompressed copy.
void load_gltf(const std::string& path, Scene& scene, const GltfLoadOptions& options = {});

}  // namespace raylab
