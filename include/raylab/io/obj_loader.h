#pragma once
/// \file
/// Wavefront OBJ meshes and their MTL materials through tinyobjloader, with every index and every
/// referenced path checked by raylab.

#include <cstdint>
#include <string>

#include "raylab/scene/mesh_builder.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// How load_obj treats the files an OBJ refers to.
struct ObjLoadOptions {
  /// Follow `mtllib` and `map_Kd` paths that leave the OBJ's folder (compared after `..` and
  /// symbolic links are resolved). Off by default: an OBJ from elsewhere must not make raylab read
  /// arbitrary files, so such a path is an InputError.
  bool allow_outside_paths = false;
  /// Use the materials of the file's `mtllib` libraries. Off: no .mtl file is read and every face
  /// goes to the caller's object.
  bool use_materials = true;
};

/// Appends the triangles of OBJ file `path` to `scene.geometry`.
///
/// Faces that a `usemtl` statement gives a material of the file's `mtllib` libraries go to an
/// object of their own per material (named "<object's name>/<material>", added with
/// Scene::add_object and Scene::add_material on first use); all other faces (no `usemtl`, a name
/// no library defines, no `mtllib` at all, or `use_materials` off) go to object `object`.
/// MTL statements map to Material as: Kd -> color (white when only map_Kd is given, so the
/// texture shows as painted), Ks -> ks (largest component), Ns -> shininess, d -> transmittance =
/// 1 - d, Ni -> ior, Ke -> emission, illum 3 to 7 (the ray-traced reflection models) ->
/// reflectivity = ks, map_Kd -> image texture (PNG or JPEG; path relative to the OBJ's folder).
/// Other statements are ignored. A material library's and a texture's path are resolved relative
/// to the OBJ's folder.
///
/// Polygons are triangulated by raylab (tinyobjloader's own triangulation reads vertices before
/// any index is validated). Vertex normals and texture coordinates (`vt`, stored per corner in
/// Geometry::triangle_uvs) are used when every corner of a face has one. Throws InputError
/// `file:line:col: ...` for an index out of range (positive or negative) of a vertex, normal or
/// texture coordinate, a non-finite number, an `mtllib` file that is missing or outside the
/// folder (at that file name in the OBJ), a `map_Kd` image that is missing, outside the folder or
/// not a valid image (at that statement in the .mtl), or a file that cannot be read.
MeshLoadReport load_obj(const std::string& path, Scene& scene, std::uint32_t object, const ObjLoadOptions& options);

/// load_obj with default options: the file's own materials when it has an `mtllib`, otherwise
/// object `object`'s material; no path may leave the OBJ's folder.
MeshLoadReport load_obj(const std::string& path, Scene& scene, std::uint32_t object);

}  // namespace raylab
