#include "raylab/io/scene_json_writer.h"

#include <nlohmann/json.hpp>

#include <map>

#include "material_model_names.h"
#include "raylab/core/error.h"
#include "raylab/io/float_text.h"
#include "raylab/io/image_io.h"
#include "raylab/io/mtl_writer.h"
#include "raylab/io/ply_writer.h"
#include "raylab/io/texture_io.h"
#include "raylab/scene/environment.h"

namespace raylab {
namespace {

// Writes the JSON text by hand rather than through nlohmann::json, whose dump() gives doubles
// 17 digits: floats here are written in their shortest form that reads back exactly.
class JsonText {
 public:
  std::string take() { return std::move(m_out); }

  // `"key": ` after the separator the enclosing object needs.
  JsonText& key(std::string_view k) {
    separate();
    m_out += nlohmann::json(std::string(k)).dump() + ": ";
    m_after_key = true;
    return *this;
  }
  JsonText& string(std::string_view s) {
    separate();
    m_out += nlohmann::json(std::string(s)).dump();
    return *this;
  }
  JsonText& number(float v) {
    separate();
    append_float_text(m_out, v);
    return *this;
  }
  JsonText& integer(long long v) {
    separate();
    m_out += std::to_string(v);
    return *this;
  }
  JsonText& boolean(bool v) {
    separate();
    m_out += v ? "true" : "false";
    return *this;
  }
  JsonText& vec(Vec3 v) { return open('[').number(v.x).number(v.y).number(v.z).close(']'); }
  // Opens an object or array; `newline` puts each member on a line of its own.
  JsonText& open(char bracket, bool newline = false) {
    separate();
    m_out += bracket;
    m_fresh = true;
    m_newline.push_back(newline);
    return *this;
  }
  JsonText& close(char bracket) {
    if (m_newline.back()) m_out += "\n" + std::string(2 * (m_newline.size() - 1), ' ');
    m_newline.pop_back();
    m_out += bracket;
    m_fresh = false;
    return *this;
  }

 private:
  // The comma (and line break) before a value or key, unless it is the first in its container
  // or the value of a key just written.
  void separate() {
    if (m_after_key) {
      m_after_key = false;
      return;
    }
    if (!m_fresh) m_out += ',';
    if (!m_newline.empty() && m_newline.back()) {
      m_out += "\n" + std::string(2 * m_newline.size(), ' ');
    } else if (!m_fresh) {
      m_out += ' ';
    }
    m_fresh = false;
  }

  std::string m_out;
  bool m_fresh = true;
  bool m_after_key = false;
  std::vector<bool> m_newline;
};

void camera_fields(JsonText& j, const CameraSpec& c) {
  j.key("from").vec(c.from).key("at").vec(c.at).key("up").vec(c.up).key("fov").number(c.vfov_degrees);
  j.key("hither").number(c.hither);
}

void camera(JsonText& j, const Scene& scene) {
  const CameraSpec& c = scene.camera;
  j.key("camera").open('{');
  camera_fields(j, c);
  j.key("fov_span").string(c.fov_span == CameraSpec::FovSpan::kImageEdges ? "edges" : "pixel-centres");
  if (!scene.camera_path.empty()) {
    const CameraPath& path = scene.camera_path;
    j.key("path").open('{');
    j.key("interpolation").string(path.interpolation == CameraPath::Interpolation::kSmooth ? "smooth" : "linear");
    j.key("keys").open('[', true);
    for (const CameraKey& k : path.keys) {
      j.open('{').key("frame").integer(k.frame);
      camera_fields(j, k.camera);
      j.close('}');
    }
    j.close(']').close('}');
  }
  j.close('}');
}

void render(JsonText& j, const RenderSettings& s) {
  j.key("render").open('{', true);
  j.key("width").integer(s.width).key("height").integer(s.height).key("spp").integer(s.spp);
  j.key("sampler").string(s.sampler).key("filter").string(s.filter).key("filter_radius").number(s.filter_radius);
  j.key("aa_threshold").number(s.aa_threshold).key("aa_depth").integer(s.aa_depth);
  j.key("max_depth").integer(s.max_depth).key("seed").integer(static_cast<long long>(s.seed));
  j.key("background").vec(s.background).key("ambient").vec(s.ambient);
  j.key("sky_gradient").boolean(s.sky_gradient).key("horizon").vec(s.horizon);
  j.key("integrator").string(s.integrator);
  j.close('}');
}

// The file each image texture is written to, by image; images 8 bits cannot give back are
// left out. Each image once, however many materials share it.
using TextureFiles = std::map<const TextureImage*, std::string>;

TextureFiles texture_files(const Scene& scene, const std::string& stem, std::vector<SidecarFile>& files) {
  TextureFiles names;
  const auto add = [&](const TextureImage* image, TextureEncoding encoding) {
    if (image == nullptr || names.count(image) > 0) return;
    const std::optional<std::vector<unsigned char>> png = encode_texture_png(*image, encoding);
    if (!png) return;
    SidecarFile file{stem + ".tex" + std::to_string(files.size()) + ".png", std::string(png->begin(), png->end())};
    names[image] = file.name;
    files.push_back(std::move(file));
  };
  for (const Material& m : scene.materials) {
    if (m.texture.kind == Texture::Kind::kImage) add(m.texture.image.get(), TextureEncoding::kSrgb);
    add(m.maps.emission.get(), TextureEncoding::kSrgb);
    for (const auto* data : {&m.maps.metallic_roughness, &m.maps.transmission, &m.maps.normal, &m.maps.bump})
      add(data->get(), TextureEncoding::kLinear);
  }
  return names;
}

// The material's maps that have a file, as "maps": {...}; nothing when none has.
void material_maps(JsonText& j, const MaterialMaps& maps, const TextureFiles& textures) {
  const auto file_of = [&](const std::shared_ptr<const TextureImage>& image) -> const std::string* {
    const auto it = image ? textures.find(image.get()) : textures.end();
    return it == textures.end() ? nullptr : &it->second;
  };
  const std::pair<const char*, const std::shared_ptr<const TextureImage>*> entries[] = {
      {"metallic_roughness", &maps.metallic_roughness},
      {"emission", &maps.emission},
      {"transmission", &maps.transmission},
      {"normal", &maps.normal},
      {"bump", &maps.bump}};
  bool open = false;
  for (const auto& [key, image] : entries) {
    const std::string* file = file_of(*image);
    if (file == nullptr) continue;
    if (!open) j.key("maps").open('{');
    open = true;
    j.key(key).open('{').key("file").string(*file);
    if (image == &maps.normal) j.key("scale").number(maps.normal_scale);
    if (image == &maps.bump) j.key("scale").number(maps.bump_scale);
    j.close('}');
  }
  if (open) j.close('}');
}

void materials(JsonText& j, const Scene& scene, const std::vector<std::string>& names, const TextureFiles& textures) {
  j.key("materials").open('{', true);
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    j.key(names[i]).open('{');
    j.key("color").vec(m.color).key("kd").number(m.kd).key("ks").number(m.ks).key("shininess").number(m.shininess);
    j.key("reflectivity").number(m.reflectivity).key("transmittance").number(m.transmittance);
    j.key("ior").number(m.ior).key("emission").vec(m.emission).key("fresnel").boolean(m.fresnel);
    // The physically based model's members, every one (a reader's defaults may change).
    j.key("type").string(std::string(detail::material_model_name(m.model))).key("roughness").number(m.roughness);
    j.key("metallic").number(m.metallic).key("transmission").number(m.transmission);
    j.key("eta").vec(m.conductor_eta).key("k").vec(m.conductor_k).key("emission_strength").number(m.emission_strength);
    if (m.texture.kind == Texture::Kind::kChecker) {
      j.key("texture").open('{').key("type").string("checker").key("color2").vec(m.texture.color2);
      j.key("scale").number(m.texture.scale).close('}');
    } else if (const auto it = textures.find(m.texture.image.get());
               m.texture.kind == Texture::Kind::kImage && it != textures.end()) {
      j.key("texture").open('{').key("type").string("image").key("file").string(it->second).close('}');
    }
    material_maps(j, m.maps, textures);
    j.close('}');
  }
  j.close('}');
}

void lights(JsonText& j, const std::vector<Light>& lights, const std::vector<SceneObject>& objects) {
  j.key("lights").open('[', true);
  for (const Light& l : lights) {
    j.open('{');
    switch (l.kind) {
      case Light::Kind::kPoint:
        j.key("type").string("point").key("position").vec(l.position).key("falloff").boolean(l.falloff);
        break;
      case Light::Kind::kDirectional:
        j.key("type").string("directional").key("direction").vec(l.direction);
        break;
      case Light::Kind::kSpot:
        j.key("type").string("spot").key("position").vec(l.position).key("direction").vec(l.direction);
        j.key("angle").number(l.spot_angle).key("blend").number(l.spot_blend).key("falloff").boolean(l.falloff);
        break;
      case Light::Kind::kSphere:
        j.key("type").string("sphere").key("center").vec(l.position).key("radius").number(l.radius);
        j.key("falloff").boolean(l.falloff).key("samples").integer(l.samples);
        break;
      case Light::Kind::kQuad:
        j.key("type").string("quad").key("corner").vec(l.position).key("edge_u").vec(l.edge_u);
        j.key("edge_v").vec(l.edge_v).key("samples").integer(l.samples);
        break;
    }
    j.key("intensity").vec(l.intensity);
    if (l.object >= 0 && static_cast<std::size_t>(l.object) < objects.size()) {
      j.key("object").string(objects[static_cast<std::size_t>(l.object)].name);
    }
    j.close('}');
  }
  j.close(']');
}

// The triangles [first, last) of `g` as a geometry of their own, for one PLY sidecar.
Geometry triangle_run(const Geometry& g, std::size_t first, std::size_t last) {
  Geometry run;
  for (std::size_t i = first; i < last; ++i) {
    run.add(g.triangles[i], g.triangle_normals.empty() ? nullptr : &g.triangle_normals[i],
            g.triangle_uvs.empty() ? nullptr : &g.triangle_uvs[i], 0);
  }
  return run;
}

class ObjectWriter {
 public:
  ObjectWriter(JsonText& j, const Scene& scene, const std::vector<std::string>& names)
      : m_j(j), m_scene(scene), m_names(names) {}

  void meshes(const std::string& stem, std::vector<SidecarFile>& files) {
    const Geometry& g = m_scene.geometry;
    for (std::size_t first = 0; first < g.triangles.size();) {
      std::size_t last = first + 1;
      while (last < g.triangles.size() && g.triangle_objects[last] == g.triangle_objects[first]) ++last;
      SidecarFile file{stem + "." + std::to_string(files.size()) + ".ply", encode_ply(triangle_run(g, first, last))};
      const std::uint32_t object = g.triangle_objects[first];
      m_j.open('{').key("type").string("mesh");
      if (object < m_scene.objects.size()) m_j.key("name").string(m_scene.objects[object].name);
      material(object);
      m_j.key("file").string(file.name).close('}');
      files.push_back(std::move(file));
      first = last;
    }
  }

  void analytic() {
    const Geometry& g = m_scene.geometry;
    for (std::size_t i = 0; i < g.spheres.size(); ++i) {
      start("sphere", g.sphere_objects[i]).key("center").vec(g.spheres[i].center);
      m_j.key("radius").number(g.spheres[i].radius).close('}');
    }
    for (std::size_t i = 0; i < g.cylinders.size(); ++i) {
      const Cylinder& c = g.cylinders[i];
      start("cone", g.cylinder_objects[i]).key("base").vec(c.base).key("base_radius").number(c.base_radius);
      m_j.key("apex").vec(c.apex).key("apex_radius").number(c.apex_radius).close('}');
    }
    for (std::size_t i = 0; i < g.disks.size(); ++i) {
      const Disk& d = g.disks[i];
      start("disk", g.disk_objects[i]).key("center").vec(d.center).key("normal").vec(d.normal);
      m_j.key("radius").number(d.radius).close('}');
    }
    for (std::size_t i = 0; i < g.quads.size(); ++i) {
      const Quad& q = g.quads[i];
      start("quad", g.quad_objects[i]).key("corner").vec(q.corner).key("edge_u").vec(q.edge_u);
      m_j.key("edge_v").vec(q.edge_v).close('}');
    }
  }

 private:
  JsonText& start(const char* type, std::uint32_t object) {
    m_j.open('{').key("type").string(type);
    // The object's name, which a light's "object" refers to.
    if (object < m_scene.objects.size()) m_j.key("name").string(m_scene.objects[object].name);
    material(object);
    return m_j;
  }

  void material(std::uint32_t object) {
    if (object < m_scene.objects.size() && m_scene.objects[object].material < m_names.size()) {
      m_j.key("material").string(m_names[m_scene.objects[object].material]);
    }
  }

  JsonText& m_j;
  const Scene& m_scene;
  const std::vector<std::string>& m_names;
};

// The environment: its colour, or its image as a float PFM beside the scene file (32-bit floats,
// so that the radiances read back bit for bit), with its rotation and scale.
void environment(JsonText& j, const Environment& e, const std::string& stem, std::vector<SidecarFile>& files) {
  j.key("environment").open('{');
  if (e.image) {
    Film film(e.image->width, e.image->height);
    for (int y = 0; y < film.height(); ++y) {
      for (int x = 0; x < film.width(); ++x) film.at(x, y) = e.image->texels[std::size_t(y) * film.width() + x];
    }
    const std::vector<unsigned char> pfm = encode_image(film, ".pfm");
    SidecarFile file{stem + ".env.pfm", std::string(pfm.begin(), pfm.end())};
    j.key("file").string(file.name);
    files.push_back(std::move(file));
  } else {
    j.key("color").vec(e.color);
  }
  j.key("rotate").number(e.rotate_degrees).key("scale").number(e.scale).close('}');
}

}  // namespace

SceneJsonFiles encode_scene_json(const Scene& scene, const std::string& stem) {
  if (!scene.instances.empty()) throw UsageError("scene file output: bake the scene's instances first");
  const std::vector<std::string> names = export_material_names(scene);
  SceneJsonFiles files;
  JsonText j;
  j.open('{', true);
  j.key("version").integer(1);
  j.key("description").string("written by raylab convert");
  camera(j, scene);
  render(j, scene.settings);
  materials(j, scene, names, texture_files(scene, stem, files.textures));
  lights(j, scene.lights, scene.objects);
  if (scene.environment) environment(j, *scene.environment, stem, files.textures);
  j.key("objects").open('[', true);
  ObjectWriter objects(j, scene, names);
  objects.meshes(stem, files.meshes);
  objects.analytic();
  j.close(']').close('}');
  files.json = j.take() + "\n";
  return files;
}

}  // namespace raylab
