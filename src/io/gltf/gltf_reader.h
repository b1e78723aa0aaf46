#pragma once
// Internal to the glTF reader: GltfReader turns a parsed, unchecked glTF model into raylab
// geometry, materials and camera, checking every index and range tinygltf leaves unchecked. Its
// members are defined by idea, one file each: the scene graph and camera (gltf_scene_graph.cpp),
// accessors (gltf_accessors.cpp), primitives (gltf_primitives.cpp), materials
// (gltf_materials.cpp) and textures (gltf_textures.cpp); the checks they share are in
// gltf_reader.cpp.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gltf_accessors.h"
#include "gltf_files.h"
#include "gltf_model.h"
#include "raylab/io/gltf_loader.h"
#include "raylab/io/texture_io.h"
#include "raylab/scene/mesh_builder.h"

namespace raylab::gltf_detail {

/// Reads one parsed glTF model into a scene; see load_gltf for what is read and refused. The
/// version and the required extensions were checked by parse_gltf.
class GltfReader {
 public:
  /// Reads `model`, parsed from `path` with the callbacks' `ctx`, into `scene`.
  GltfReader(std::string path, const tinygltf::Model& model, CallbackContext& ctx, Scene& scene,
             const GltfLoadOptions& options)
      : m_path(std::move(path)), m_model(model), m_ctx(ctx), m_scene(scene), m_options(options) {}

  /// Adds the default scene's meshes (and camera, when asked for) to the scene.
  void read();

 private:
  // --- Shared checks (gltf_reader.cpp)

  /// Throws InputError `path: element: message`.
  [[noreturn]] void fail(const std::string& element, const std::string& message) const;
  /// Adds `path: message` to the scene's warnings.
  void warn(const std::string& message);
  /// Checks that `index` names one of `size` elements of array `array`.
  void check_index(int index, std::size_t size, const std::string& element, const char* array) const;

  // --- Scene graph and camera (gltf_scene_graph.cpp)

  /// The default scene's nodes, or scene 0's, or, with no scenes, every node without a parent.
  std::vector<int> root_nodes() const;
  /// Visits the nodes below `roots` depth first, parents before children, without recursion (a
  /// hostile file can nest nodes deeper than any stack). glTF nodes form trees: a node reached
  /// twice is an error, which also catches cycles and the exponential blow-up of shared subtrees.
  void traverse(const std::vector<int>& roots);
  /// A node's own transform: its matrix, or translation x rotation x scale.
  Transform local_transform(const tinygltf::Node& node, const std::string& element) const;
  /// The first perspective camera met becomes the scene's camera, when asked for.
  void take_camera(int index, const Transform& world, const std::string& element);

  // --- Accessors (gltf_accessors.cpp)

  /// Accessor `index` for `use` by `user`, checked against its buffer view and buffer.
  AccessorData accessor(int index, const AccessorUse& use, const std::string& user) const;
  /// The bytes of buffer view `index`, checked to lie inside its buffer.
  std::span<const unsigned char> view_bytes(int index) const;
  /// The float vectors of accessor `a` (attribute `name` of `element`), every value checked finite.
  std::vector<float> read_floats(const AccessorData& a, const std::string& element, const char* name) const;

  // --- Primitives (gltf_primitives.cpp)

  /// Adds every primitive of mesh `index`, placed by `world`.
  void add_mesh(int index, const Transform& world, const std::string& node_element);
  /// Adds the triangles of primitive `p`; points and lines are skipped with a warning.
  void add_primitive(const tinygltf::Primitive& p, const Transform& world, const std::string& element);
  /// The corner indices of a primitive's triangles, in triangle-list order.
  std::vector<std::uint32_t> triangle_corners(const tinygltf::Primitive& p, std::size_t vertex_count,
                                              const std::string& element) const;
  /// Strips and fans as triangle lists (strips alternate their winding back).
  std::vector<std::uint32_t> unroll(const std::vector<std::uint32_t>& in, int mode, const std::string& element) const;
  /// Adds the triangles `corners` of the vertex arrays (3, 3 and 2 floats a vertex), placed by
  /// `world`, as object `object`.
  void add_triangles(const std::vector<std::uint32_t>& corners, const std::vector<float>& positions,
                     const std::vector<float>& normals, const std::vector<float>& uvs, const Transform& world,
                     std::uint32_t object);

  // --- Materials (gltf_materials.cpp)

  /// The object of glTF material `index` (-1: none), created with its material on first use.
  /// Also records which TEXCOORD set the material's textures read (-1: none).
  std::uint32_t object_for(int index, const std::string& user);
  /// The raylab material of glTF material `index`.
  Material convert_material(int index);
  /// The image of a texture reference of material `material` (`element` names it, texCoord
  /// `tex_coord`), decoded with `encoding`; the material's set of texture coordinates becomes
  /// tex_coord (raylab keeps one set per material: a second set is warned about and read as the
  /// first).
  std::shared_ptr<const TextureImage> material_texture(int material, int texture, int tex_coord,
                                                       const std::string& element, TextureEncoding encoding);

  // --- Textures (gltf_textures.cpp)

  /// The image of texture `index` (used by `user`), decoded on first use with `encoding`.
  std::shared_ptr<const TextureImage> texture(int index, const std::string& user,
                                              TextureEncoding encoding = TextureEncoding::kSrgb);
  /// Decodes image `index`, from its buffer view or from the bytes its URI gave.
  std::shared_ptr<const TextureImage> decode_image(int index, TextureEncoding encoding);

  std::string m_path;
  const tinygltf::Model& m_model;
  CallbackContext& m_ctx;
  Scene& m_scene;
  GltfLoadOptions m_options;
  MeshLoadReport m_report;
  bool m_camera_taken = false;
  std::vector<std::optional<std::uint32_t>> m_objects;  // by material index + 1
  std::vector<int> m_uv_set;                            // by material index + 1
  // By image index and encoding: one image may serve as colour (sRGB) and as data (linear).
  std::map<std::pair<int, TextureEncoding>, std::shared_ptr<const TextureImage>> m_images;
};

}  // namespace raylab::gltf_detail
