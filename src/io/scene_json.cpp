#include "raylab/io/scene_json.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "json_document.h"
#include "material_model_names.h"
#include "raylab/core/error.h"
#include "raylab/io/environment_io.h"
#include "raylab/io/read_file.h"
#include "raylab/io/scene_loader.h"
#include "raylab/io/texture_io.h"
#include "raylab/render/integrator.h"
#include "raylab/render/renderer.h"
#include "raylab/sampling/filter.h"
#include "raylab/scene/environment.h"
#include "raylab/scene/mesh_builder.h"
#include "raylab/scene/metals.h"
#include "raylab/scene/scene_merge.h"
#include "raylab/scene/spd.h"
#include "scene_json_camera.h"
#include "scene_json_node.h"

namespace raylab {
namespace {

using nlohmann::json;
using scene_json_detail::kPositive;
using scene_json_detail::kRequired;
using scene_json_detail::Node;
using scene_json_detail::read_camera;
using scene_json_detail::type_name;

class SceneReader {
 public:
  SceneReader(const JsonDocument& doc, std::string base_dir, const LoadOptions& options)
      : m_doc(doc), m_base_dir(std::move(base_dir)), m_options(options) {}

  Scene read() {
    const Node root(m_doc, m_doc.root(), "", "the scene");
    root.check_keys({"$schema", "version", "description", "camera", "render", "materials", "lights", "environment",
                     "meshes", "objects"});
    if (!root.has("version")) root.fail("the scene needs \"version\": " + std::to_string(kSceneFormatVersion));
    const std::int64_t version = root.integer("version", 0, 0, 1 << 30);
    if (version != kSceneFormatVersion) {
      root.fail_at("version", "scene format version " + std::to_string(version) +
                                  " is not supported (this raylab reads version " +
                                  std::to_string(kSceneFormatVersion) + ")");
    }
    if (root.has("description")) (void)root.string("description");
    if (root.has("render")) read_render(root.child("render", "'render'"));
    if (root.has("materials")) read_materials(root.child("materials", "'materials'"));
    if (root.has("lights")) read_lights(root.child("lights", "'lights'"));
    if (root.has("environment")) read_environment(root.child("environment", "'environment'"));
    if (root.has("meshes")) read_meshes(root.child("meshes", "'meshes'"));
    if (!root.has("objects")) root.fail("the scene needs 'objects' (an array)");
    read_objects(root.child("objects", "'objects'"));
    resolve_light_objects();
    if (m_scene.primitive_count() == 0) root.fail_at("objects", "the scene has no primitives");
    const bool has_camera = root.has("camera");
    const bool has_lights = root.has("lights");
    if (has_camera) read_camera(root.child("camera", "'camera'"), m_scene.camera, m_scene.camera_path);
    // Lights and camera of an SPD generator serve when the file gives none; otherwise the
    // camera is fitted to the scene's bounds, as for a bare mesh.
    if (!has_lights && m_borrowed) m_scene.lights = m_borrowed->lights;
    if (!has_camera && m_borrowed) m_scene.camera = m_borrowed->camera;
    if (!has_camera && !m_borrowed) {
      const std::vector<Light> lights = m_scene.lights;
      const RenderSettings settings = m_scene.settings;
      fit_camera_and_lights(m_scene);
      m_scene.settings = settings;
      if (has_lights) {
        m_scene.lights = lights;
        m_scene.lights_fitted = false;
      }
    } else if (!has_lights && !m_borrowed) {
      root.fail("the scene has a camera but no 'lights'");
    }
    return std::move(m_scene);
  }

 private:
  void read_render(const Node& n) {
    n.check_keys({"width", "height", "spp", "sampler", "filter", "filter_radius", "aa_threshold", "aa_depth",
                  "max_depth", "seed", "background", "ambient", "sky_gradient", "horizon", "integrator"});
    RenderSettings& s = m_scene.settings;
    s.width = static_cast<int>(n.integer("width", s.width, 1, 32768));
    s.height = static_cast<int>(n.integer("height", s.height, 1, 32768));
    s.spp = static_cast<int>(n.integer("spp", s.spp, 1, 1 << 16));
    std::vector<std::string_view> samplers{"auto"};
    for (std::string_view name : render_sampler_names()) samplers.push_back(name);
    s.sampler = n.choice("sampler", samplers, s.sampler);
    s.filter = n.choice("filter", filter_names(), s.filter);
    s.integrator = n.choice("integrator", integrator_names(), s.integrator);
    s.filter_radius = static_cast<float>(n.real("filter_radius", 0.0, 0.0, 8.0));
    if (s.filter_radius != 0.f && s.filter_radius < 0.5f)
      n.fail_at("filter_radius", "'filter_radius' must be 0 (the filter's default) or at least 0.5");
    s.aa_threshold = static_cast<float>(n.real("aa_threshold", -1.0, -1.0, 1.0));
    s.aa_depth = static_cast<int>(n.integer("aa_depth", -1, -1, 8));
    s.max_depth = static_cast<int>(n.integer("max_depth", s.max_depth, 1, 64));
    s.seed = static_cast<std::uint64_t>(n.integer("seed", 0, 0, std::numeric_limits<std::int64_t>::max()));
    s.background = n.color("background", s.background);
    s.ambient = n.color("ambient", s.ambient);
    s.sky_gradient = n.boolean("sky_gradient", s.sky_gradient);
    s.horizon = n.color("horizon", s.horizon);
  }

  void read_materials(const Node& n) {
    if (!n.value().is_object()) n.fail("'materials' must be an object mapping names to materials");
    for (const auto& item : n.value().items()) {
      const Node m = n.child(item.key(), "material '" + item.key() + "'");
      m.check_keys({"type", "color", "kd", "ks", "shininess", "reflectivity", "transmittance", "ior", "emission",
                    "emission_strength", "fresnel", "texture", "roughness", "metal", "eta", "k", "metallic",
                    "transmission", "maps"});
      Material mat;
      mat.name = item.key();
      read_material_model(m, mat);
      mat.color = m.color("color", mat.color);
      mat.kd = m.real("kd", mat.kd, 0.0);
      mat.ks = m.real("ks", mat.ks, 0.0);
      mat.shininess = m.real("shininess", mat.shininess, 0.0);
      mat.reflectivity = m.real("reflectivity", mat.reflectivity, 0.0, 1.0);
      mat.transmittance = m.real("transmittance", mat.transmittance, 0.0, 1.0);
      mat.ior = m.real("ior", mat.ior, 1e-3, 100.0);
      mat.emission = m.color("emission", mat.emission);
      mat.fresnel = m.boolean("fresnel", mat.fresnel);
      if (m.has("texture")) read_texture(m.child("texture", "texture of material '" + item.key() + "'"), mat);
      if (m.has("maps")) read_maps(m.child("maps", "maps of material '" + item.key() + "'"), mat.maps);
      m_materials[item.key()] = m_scene.add_material(mat);
    }
  }

  // The physically based part of a material: its "type" and that model's parameters (the
  // Phong keys above stay what Whitted shades; docs/scene-format.md).
  static void read_material_model(const Node& m, Material& mat) {
    std::vector<std::string_view> names;
    for (const auto& [name, model] : detail::kMaterialModelNames) names.push_back(name);
    const std::string type = m.choice("type", names, "phong");
    for (const auto& [name, model] : detail::kMaterialModelNames) {
      if (name == type) mat.model = model;
    }
    mat.roughness = static_cast<float>(m.real("roughness", mat.roughness, 0.0, 1.0));
    mat.metallic = static_cast<float>(m.real("metallic", mat.metallic, 0.0, 1.0));
    mat.transmission = static_cast<float>(m.real("transmission", mat.transmission, 0.0, 1.0));
    mat.emission_strength = static_cast<float>(m.real("emission_strength", mat.emission_strength, 0.0));
    if (m.has("metal")) {
      if (m.has("eta") || m.has("k")) m.fail_at("metal", "give either 'metal' or 'eta' and 'k', not both");
      const std::string metal = m.string("metal");
      const std::optional<ConductorIor> ior = metal_ior(metal);
      if (!ior) m.fail_at("metal", "unknown metal '" + metal + "' (known: gold, copper, aluminium, silver)");
      mat.conductor_eta = ior->eta;
      mat.conductor_k = ior->k;
    }
    mat.conductor_eta = m.color("eta", mat.conductor_eta);
    mat.conductor_k = m.color("k", mat.conductor_k);
  }

  // The environment: {"color": [r, g, b]} or {"file": "sky.exr"}, with "rotate" (degrees about
  // +y) and "scale".
  void read_environment(const Node& n) {
    n.check_keys({"color", "file", "rotate", "scale"});
    if (n.has("color") == n.has("file")) n.fail("the environment needs exactly one of 'color' and 'file'");
    const auto rotate = static_cast<float>(n.real("rotate", 0.0));
    Environment env;
    if (n.has("color")) {
      env.color = n.color("color", env.color);
      env.rotate_degrees = rotate;
    } else {
      const std::string reference = n.string("file");
      const std::string path = resolve_scene_path(m_base_dir, reference, m_options.allow_outside_paths);
      if (path.empty()) n.fail_at("file", outside_message(reference));
      check_exists(n, reference, path, "environment");
      env = load_environment(path, rotate, "environment image");
      m_scene.source_files.push_back(path);
    }
    env.scale = static_cast<float>(n.real("scale", 1.0, 0.0));
    m_scene.environment = std::make_shared<Environment>(std::move(env));
  }

  void read_texture(const Node& t, Material& mat) {
    const std::string type = t.choice("type", {"checker", "image"});
    if (type == "image") {
      // An image multiplies the material's colour (set "color": 1 to show it as painted).
      t.check_keys({"type", "file"});
      const std::string reference = t.string("file");
      const std::string path = resolve_scene_path(m_base_dir, reference, m_options.allow_outside_paths);
      if (path.empty()) t.fail_at("file", outside_message(reference));
      try {
        mat.texture = Texture::from_image(load_texture(path));
      } catch (const InputError&) {
        check_exists(t, reference, path, "texture");
        throw;
      }
      return;
    }
    t.check_keys({"type", "color2", "scale"});
    mat.texture.kind = Texture::Kind::kChecker;
    mat.texture.color2 = t.color("color2", mat.texture.color2);
    mat.texture.scale = t.real("scale", mat.texture.scale, kPositive);
  }

  // The maps beyond the colour (docs/scene-format.md): each {"file": ...}, the normal and bump
  // maps with an optional "scale".
  void read_maps(const Node& n, MaterialMaps& maps) {
    if (!n.value().is_object()) n.fail("'maps' must be an object");
    n.check_keys({"metallic_roughness", "emission", "transmission", "normal", "bump"});
    const auto image = [&](const char* key, TextureEncoding encoding, float* scale) {
      const Node t = n.child(key, std::string(key) + " map");
      if (!t.value().is_object()) t.fail("a map must be an object with a 'file'");
      t.check_keys(scale != nullptr ? std::initializer_list<std::string_view>{"file", "scale"}
                                    : std::initializer_list<std::string_view>{"file"});
      if (scale != nullptr) *scale = static_cast<float>(t.real("scale", *scale));
      const std::string reference = t.string("file");
      const std::string path = resolve_scene_path(m_base_dir, reference, m_options.allow_outside_paths);
      if (path.empty()) t.fail_at("file", outside_message(reference));
      try {
        return load_texture(path, encoding);
      } catch (const InputError&) {
        check_exists(t, reference, path, "map");
        throw;
      }
    };
    constexpr TextureEncoding kSrgb = TextureEncoding::kSrgb, kLinear = TextureEncoding::kLinear;
    if (n.has("metallic_roughness")) maps.metallic_roughness = image("metallic_roughness", kLinear, nullptr);
    if (n.has("emission")) maps.emission = image("emission", kSrgb, nullptr);
    if (n.has("transmission")) maps.transmission = image("transmission", kLinear, nullptr);
    if (n.has("normal")) maps.normal = image("normal", kLinear, &maps.normal_scale);
    if (n.has("bump")) maps.bump = image("bump", kLinear, &maps.bump_scale);
  }

  // Fails at `n`'s "file" when `path` is not a file: a missing file is a mistake in the scene
  // file, reported at the reference (the file's own name could not say which line wanted it).
  static void check_exists(const Node& n, const std::string& reference, const std::string& path, const char* what) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return;
    n.fail_at("file", std::string(what) + " file '" + reference + "' not found (looked for " + path + ")");
  }

  static std::string outside_message(const std::string& reference) {
    return "'" + reference +
           "' is outside the scene's folder; pass --allow-outside-paths to allow references that leave it";
  }

  void read_lights(const Node& n) {
    if (!n.value().is_array()) n.fail("'lights' must be an array");
    for (std::size_t i = 0; i < n.value().size(); ++i) {
      const Node l = n.element(i, "light " + std::to_string(i));
      if (!l.value().is_object()) l.fail("a light must be an object");
      const std::string type = l.choice("type", {"point", "spot", "directional", "sphere", "quad"});
      Light light;
      light.intensity = l.color("intensity", light.intensity);
      if (type == "point") {
        l.check_keys({"type", "position", "intensity", "falloff"});
        light.kind = Light::Kind::kPoint;
        light.position = l.vec3("position");
        light.falloff = l.boolean("falloff", false);
      } else if (type == "spot") {
        l.check_keys({"type", "position", "direction", "angle", "blend", "intensity", "falloff"});
        light.kind = Light::Kind::kSpot;
        light.position = l.vec3("position");
        light.direction = l.vec3("direction");
        if (!(dot(light.direction, light.direction) > 0.f)) l.fail_at("direction", "'direction' must not be zero");
        light.direction = normalize(light.direction);
        light.spot_angle = l.real("angle", light.spot_angle, kPositive, 90.0);
        light.spot_blend = l.real("blend", light.spot_blend, 0.0, 1.0);
        light.falloff = l.boolean("falloff", false);
      } else if (type == "directional") {
        l.check_keys({"type", "direction", "intensity"});
        light.kind = Light::Kind::kDirectional;
        light.direction = l.vec3("direction");
        if (!(dot(light.direction, light.direction) > 0.f)) l.fail_at("direction", "'direction' must not be zero");
        light.direction = normalize(light.direction);
      } else if (type == "sphere") {
        l.check_keys({"type", "center", "radius", "intensity", "falloff", "samples", "object"});
        light.kind = Light::Kind::kSphere;
        light.position = l.vec3("center");
        light.radius = l.real("radius", kRequired, 0.0);
        light.falloff = l.boolean("falloff", false);
        light.samples = static_cast<int>(l.integer("samples", light.samples, 1, 4096));
      } else {
        l.check_keys({"type", "corner", "edge_u", "edge_v", "intensity", "samples", "object"});
        light.kind = Light::Kind::kQuad;
        light.position = l.vec3("corner");
        light.edge_u = l.vec3("edge_u");
        light.edge_v = l.vec3("edge_v");
        light.samples = static_cast<int>(l.integer("samples", light.samples, 1, 4096));
      }
      if (l.has("object")) m_light_objects.emplace_back(m_scene.lights.size(), l, l.string("object"));
      m_scene.lights.push_back(light);
    }
  }

  // The objects that sphere and quad lights name as their visible surface ("object"), once the
  // objects are read: the path integrator lights the scene from the object and skips the light.
  void resolve_light_objects() {
    for (const auto& entry : m_light_objects) {
      // Named variables, not a structured binding: clang 14 cannot capture a binding in a lambda.
      const std::size_t light = std::get<0>(entry);
      const Node& node = std::get<1>(entry);
      const std::string& name = std::get<2>(entry);
      const auto& objects = m_scene.objects;
      const auto it =
          std::find_if(objects.begin(), objects.end(), [&](const SceneObject& o) { return o.name == name; });
      if (it == objects.end()) node.fail_at("object", "no object is named '" + name + "'");
      m_scene.lights[light].object = static_cast<std::int32_t>(it - objects.begin());
    }
  }

  void read_meshes(const Node& n) {
    if (!n.value().is_object()) n.fail("'meshes' must be an object mapping names to mesh files");
    for (const auto& item : n.value().items()) {
      const Node m = n.child(item.key(), "mesh '" + item.key() + "'");
      m.check_keys({"file"});
      m_meshes.emplace(item.key(), load_referenced_mesh(m));
    }
  }

  Scene load_referenced_mesh(const Node& n) {
    const std::string reference = n.string("file");
    const std::string path = resolve_scene_path(m_base_dir, reference, m_options.allow_outside_paths);
    if (path.empty()) n.fail_at("file", outside_message(reference));
    try {
      return load_mesh(path, m_options);
    } catch (const UsageError& e) {
      // An extension no loader reads is a mistake in this file, at this reference.
      n.fail_at("file", e.what());
    } catch (const InputError&) {
      check_exists(n, reference, path, "mesh");
      throw;  // an error inside the mesh file, at its own line and column
    }
  }

  std::optional<std::uint32_t> material_of(const Node& o, bool required) {
    if (!o.has("material")) {
      if (required) o.fail("the object needs a 'material'" + material_list());
      return std::nullopt;
    }
    const std::string name = o.string("material");
    const auto it = m_materials.find(name);
    if (it == m_materials.end()) o.fail_at("material", "unknown material '" + name + "'" + material_list());
    return it->second;
  }

  std::string material_list() const {
    std::string names;
    for (const auto& [name, index] : m_materials) names += (names.empty() ? "" : ", ") + name;
    return names.empty() ? " (the scene defines no materials)" : " (defined: " + names + ")";
  }

  Transform read_transform(const Node& o) {
    if (!o.has("transform")) return Transform::identity();
    const Node t = o.child("transform", "'transform'");
    Transform out = Transform::identity();
    if (t.value().is_object()) return read_transform_step(t);
    if (!t.value().is_array()) t.fail("'transform' must be an object or an array of them");
    // Steps apply in the order written: the first one is applied to the object first.
    for (std::size_t i = 0; i < t.value().size(); ++i) out = read_transform_step(t.element(i, "transform step")) * out;
    if (!out.valid()) t.fail("the transform is not invertible");
    return out;
  }

  Transform read_transform_step(const Node& s) {
    s.check_keys({"translate", "rotate", "scale", "matrix"});
    if (s.value().size() != 1) s.fail("a transform step has exactly one of translate, rotate, scale, matrix");
    if (s.has("translate")) {
      const Vec3 v = s.vec3("translate");
      return Transform::translate(v.x, v.y, v.z);
    }
    if (s.has("scale")) {
      if (s.value().at("scale").is_number()) {
        const double k = s.number("scale");
        if (k == 0.0) s.fail_at("scale", "'scale' must not be zero");
        return Transform::scale(k, k, k);
      }
      const Vec3 v = s.vec3("scale");
      if (v.x == 0.f || v.y == 0.f || v.z == 0.f) s.fail_at("scale", "'scale' must not have a zero component");
      return Transform::scale(v.x, v.y, v.z);
    }
    if (s.has("rotate")) {
      const Node r = s.child("rotate", "'rotate'");
      r.check_keys({"axis", "degrees"});
      const Vec3 axis = r.vec3("axis");
      if (!(dot(axis, axis) > 0.f)) r.fail_at("axis", "'axis' must not be zero");
      return Transform::rotate(r.number("degrees"), axis);
    }
    const json& m = s.value().at("matrix");
    if (!m.is_array() || m.size() != 16) s.fail_at("matrix", "'matrix' must be an array of 16 numbers (row-major 4x4)");
    std::array<double, 12> rows{};
    for (std::size_t i = 0; i < 16; ++i) {
      if (!m[i].is_number() || !std::isfinite(m[i].get<double>()))
        s.fail_at("matrix", "'matrix' entries must be finite numbers");
      if (i < 12) rows[i] = m[i].get<double>();
    }
    if (m[12].get<double>() != 0.0 || m[13].get<double>() != 0.0 || m[14].get<double>() != 0.0 ||
        m[15].get<double>() != 1.0) {
      s.fail_at("matrix", "'matrix' must be affine: its last row must be 0 0 0 1");
    }
    return Transform::from_rows(rows);
  }

  void read_objects(const Node& n) {
    if (!n.value().is_array()) n.fail("'objects' must be an array");
    for (std::size_t i = 0; i < n.value().size(); ++i) {
      const Node o = n.element(i, "object " + std::to_string(i));
      if (!o.value().is_object()) o.fail("an object must be a JSON object, found " + type_name(o.value()));
      const std::string type = o.choice(
          "type", {"sphere", "cylinder", "cone", "disk", "quad", "triangle", "polygon", "mesh", "instance", "spd"});
      read_object(o, type, i);
    }
  }

  void read_object(const Node& o, const std::string& type, std::size_t index) {
    const std::string name = o.string("name", type + " " + std::to_string(index));
    Geometry& g = m_scene.geometry;
    try {
      if (type == "sphere") {
        o.check_keys({"type", "name", "material", "center", "radius"});
        const std::uint32_t obj = m_scene.add_object(name, *material_of(o, true));
        g.add(Sphere{o.vec3("center"), o.real("radius", kRequired, kPositive)}, obj);
      } else if (type == "cylinder") {
        o.check_keys({"type", "name", "material", "base", "apex", "radius"});
        const std::uint32_t obj = m_scene.add_object(name, *material_of(o, true));
        const float r = o.real("radius", kRequired, kPositive);
        g.add(Cylinder{o.vec3("base"), r, o.vec3("apex"), r}, obj);
      } else if (type == "cone") {
        o.check_keys({"type", "name", "material", "base", "base_radius", "apex", "apex_radius"});
        const std::uint32_t obj = m_scene.add_object(name, *material_of(o, true));
        const float r0 = o.real("base_radius", kRequired, 0.0), r1 = o.real("apex_radius", kRequired, 0.0);
        if (r0 == 0.f && r1 == 0.f) o.fail("a cone needs a radius above zero at one end at least");
        g.add(Cylinder{o.vec3("base"), r0, o.vec3("apex"), r1}, obj);
      } else if (type == "disk") {
        o.check_keys({"type", "name", "material", "center", "normal", "radius"});
        const std::uint32_t obj = m_scene.add_object(name, *material_of(o, true));
        const Vec3 normal = o.vec3("normal");
        if (!(dot(normal, normal) > 0.f)) o.fail_at("normal", "'normal' must not be zero");
        g.add(Disk{o.vec3("center"), normalize(normal), o.real("radius", kRequired, kPositive)}, obj);
      } else if (type == "quad") {
        o.check_keys({"type", "name", "material", "corner", "edge_u", "edge_v"});
        const std::uint32_t obj = m_scene.add_object(name, *material_of(o, true));
        const Quad q{o.vec3("corner"), o.vec3("edge_u"), o.vec3("edge_v")};
        const Vec3 n = cross(q.edge_u, q.edge_v);
        if (!(dot(n, n) > 0.f)) o.fail("the quad's edges are parallel (zero area)");
        g.add(q, obj);
      } else if (type == "triangle" || type == "polygon") {
        o.check_keys({"type", "name", "material", "vertices"});
        const std::uint32_t obj = m_scene.add_object(name, *material_of(o, true));
        read_polygon(o, obj, type == "triangle");
      } else if (type == "mesh") {
        o.check_keys({"type", "name", "material", "file", "transform"});
        const std::optional<std::uint32_t> material = material_of(o, false);
        const Transform placement = read_transform(o);
        append_scene(m_scene, load_referenced_mesh(o), placement, material);
      } else if (type == "instance") {
        o.check_keys({"type", "name", "material", "mesh", "transform"});
        const std::string mesh = o.string("mesh");
        const auto it = m_meshes.find(mesh);
        if (it == m_meshes.end()) o.fail_at("mesh", "unknown mesh '" + mesh + "'" + mesh_list());
        place_instance(name, mesh, it->second, read_transform(o), material_of(o, false));
      } else {
        o.check_keys({"type", "name", "material", "generator", "size", "transform"});
        std::string source = "spd:" + o.string("generator");
        if (o.has("size")) source += "?size=" + std::to_string(o.integer("size", 1, 1, 1 << 20));
        check_spd_size(o);
        Scene spd = make_spd_scene(source);
        append_scene(m_scene, spd, read_transform(o), material_of(o, false));
        if (!m_borrowed) m_borrowed = std::move(spd);
      }
    } catch (const UsageError& e) {
      // Generator names and transforms that cannot apply are errors in the file, at this object.
      o.fail(e.what());
    }
  }

  // Refuses an SPD object larger than LoadOptions::max_spd_size allows.
  void check_spd_size(const Node& o) const {
    if (m_options.max_spd_size <= 0) return;
    const std::string name = o.string("generator");
    for (const SpdGenerator& g : spd_generators()) {
      if (g.name != name) continue;
      const auto size = o.has("size") ? o.integer("size", 1, 1, 1 << 20) : g.default_size;
      if (size > m_options.max_spd_size) {
        o.fail("SPD size " + std::to_string(size) + " is over this reader's limit of " +
               std::to_string(m_options.max_spd_size));
      }
    }
  }

  void read_polygon(const Node& o, std::uint32_t obj, bool triangle) {
    if (!o.has("vertices")) o.fail("the object needs 'vertices'");
    const Node v = o.child("vertices", "'vertices'");
    if (!v.value().is_array() || v.value().size() < 3 || (triangle && v.value().size() != 3)) {
      v.fail(std::string("'vertices' must be an array of ") + (triangle ? "3" : "3 or more") + " points");
    }
    std::vector<Vec3> corners;
    for (std::size_t k = 0; k < v.value().size(); ++k) {
      corners.push_back(o.to_vec3(v.value()[k], v.pointer() + "/" + std::to_string(k), "vertices"));
    }
    MeshLoadReport report;
    add_polygon(m_scene.geometry, corners, {}, {}, obj, report);
    if (report.triangles == 0) o.fail("the polygon has zero area");
  }

  // An instance of a named mesh: the mesh's geometry becomes a prototype the first time it is
  // placed (stored once), and each placement gets its own objects, so materials can differ.
  void place_instance(const std::string& name, const std::string& mesh_name, const Scene& mesh,
                      const Transform& to_world, std::optional<std::uint32_t> material) {
    auto [it, fresh] = m_prototypes.try_emplace(mesh_name);
    PrototypeInfo& proto = it->second;
    if (fresh) {
      proto.index = static_cast<std::uint32_t>(m_scene.prototypes.size());
      m_scene.prototypes.push_back(mesh.geometry);
      for (const Material& m : mesh.materials) proto.materials.push_back(m_scene.add_material(m));
    }
    const auto first_object = static_cast<std::uint32_t>(m_scene.objects.size());
    for (const SceneObject& obj : mesh.objects) {
      m_scene.add_object(name.empty() ? obj.name : name + "/" + obj.name,
                         material ? *material : proto.materials[obj.material]);
    }
    m_scene.add_instance(proto.index, to_world, first_object);
  }

  std::string mesh_list() const {
    std::string names;
    for (const auto& [name, mesh] : m_meshes) names += (names.empty() ? "" : ", ") + name;
    return names.empty() ? " (the scene defines no 'meshes')" : " (defined: " + names + ")";
  }

  const JsonDocument& m_doc;
  std::string m_base_dir;
  LoadOptions m_options;
  Scene m_scene;
  std::map<std::string, std::uint32_t> m_materials;
  std::vector<std::tuple<std::size_t, Node, std::string>> m_light_objects;  // light, where named, object name
  std::map<std::string, Scene> m_meshes;                                    // loaded once, placed by every instance
  struct PrototypeInfo {
    std::uint32_t index = 0;               // into Scene::prototypes
    std::vector<std::uint32_t> materials;  // the mesh's materials, as added to the scene
  };
  std::map<std::string, PrototypeInfo> m_prototypes;  // meshes placed so far
  std::optional<Scene> m_borrowed;                    // the first SPD generator's scene: camera and lights
};

}  // namespace

Scene parse_scene_json(std::string_view text, const std::string& file, const std::string& base_dir,
                       const LoadOptions& options) {
  const JsonDocument doc(text, file);
  return SceneReader(doc, base_dir, options).read();
}

Scene load_scene_json(const std::string& path, const LoadOptions& options) {
  const std::string text = read_file(path);
  return parse_scene_json(text, path, folder_of(path), options);
}

}  // namespace raylab
