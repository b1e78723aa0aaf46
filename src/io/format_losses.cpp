#include "raylab/io/format_losses.h"

#include <algorithm>
#include <functional>

#include "raylab/io/texture_io.h"
#include "raylab/scene/environment.h"

namespace raylab {
namespace {

// "1 sphere", "3 spheres" (plural by adding `plural_suffix`).
std::string count(std::size_t n, std::string_view noun, std::string_view plural_suffix = "s") {
  return std::to_string(n) + " " + std::string(noun) + (n == 1 ? "" : std::string(plural_suffix));
}

std::size_t count_if(const std::vector<Material>& materials, const std::function<bool(const Material&)>& pred) {
  std::size_t n = 0;
  for (const Material& m : materials) n += pred(m) ? 1 : 0;
  return n;
}

bool nonzero(Color c) { return c.x != 0.f || c.y != 0.f || c.z != 0.f; }

// Materials that some primitive uses.
std::size_t used_materials(const Scene& scene) {
  std::vector<bool> used(scene.materials.size(), false);
  const Geometry& g = scene.geometry;
  for (std::uint32_t prim = 0; prim < g.size(); ++prim) {
    const std::uint32_t object = g.object_of(prim);
    if (object < scene.objects.size() && scene.objects[object].material < used.size()) {
      used[scene.objects[object].material] = true;
    }
  }
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
}

// The render settings that differ from the defaults, by name; `kept` says which a format keeps.
std::vector<std::string> changed_settings(const RenderSettings& s, const std::function<bool(std::string_view)>& kept) {
  const RenderSettings d;
  const std::pair<std::string_view, bool> all[] = {
      {"size", s.width != d.width || s.height != d.height},
      {"spp", s.spp != d.spp},
      {"sampler", s.sampler != d.sampler},
      {"filter", s.filter != d.filter || s.filter_radius != d.filter_radius},
      {"adaptive settings", s.aa_threshold != d.aa_threshold || s.aa_depth != d.aa_depth},
      {"depth", s.max_depth != d.max_depth},
      {"seed", s.seed != d.seed},
      {"background", s.background != d.background},
      {"ambient", s.ambient != d.ambient},
      {"sky gradient", s.sky_gradient != d.sky_gradient || s.horizon != d.horizon},
  };
  std::vector<std::string> out;
  for (const auto& [name, changed] : all)
    if (changed && !kept(name)) out.emplace_back(name);
  return out;
}

void add_settings(std::vector<std::string>& out, const RenderSettings& s,
                  const std::function<bool(std::string_view)>& kept) {
  const std::vector<std::string> lost = changed_settings(s, kept);
  if (lost.empty()) return;
  std::string item = "render settings (";
  for (std::size_t i = 0; i < lost.size(); ++i) item += (i ? ", " : "") + lost[i];
  out.push_back(item + ")");
}

void add_if(std::vector<std::string>& out, std::size_t n, const std::string& item) {
  if (n > 0) out.push_back(item);
}

// Textures a format cannot carry: a zone plate has no syntax anywhere; an image has no file
// name left, so only a scene file, which writes it as a PNG beside it, keeps one (when 8 bits
// give its texels back); a checker only a scene file.
void add_texture_losses(std::vector<std::string>& out, const Scene& scene, bool scene_file) {
  const bool checker_kept = scene_file;
  const auto& ms = scene.materials;
  const std::size_t images = count_if(ms, [&](const Material& m) {
    if (m.texture.kind != Texture::Kind::kImage) return false;
    return !scene_file || m.texture.image == nullptr || !encode_texture_png(*m.texture.image);
  });
  const std::size_t plates =
      count_if(ms, [](const Material& m) { return m.texture.kind == Texture::Kind::kZonePlate; });
  const std::size_t checkers =
      checker_kept ? 0 : count_if(ms, [](const Material& m) { return m.texture.kind == Texture::Kind::kChecker; });
  add_if(out, images, count(images, "image texture"));
  // The maps (normal, bump, emission, metallic-roughness, transmission): only a scene file
  // carries them, as PNGs beside it, where 8 bits give their texels back.
  const std::size_t mapped = count_if(ms, [&](const Material& m) {
    const MaterialMaps& p = m.maps;
    const auto lost = [&](const std::shared_ptr<const TextureImage>& image, TextureEncoding encoding) {
      return image != nullptr && (!scene_file || !encode_texture_png(*image, encoding));
    };
    constexpr TextureEncoding kLinear = TextureEncoding::kLinear;
    return lost(p.metallic_roughness, kLinear) || lost(p.emission, TextureEncoding::kSrgb) ||
           lost(p.transmission, kLinear) || lost(p.normal, kLinear) || lost(p.bump, kLinear);
  });
  add_if(out, mapped, "texture maps beyond the colour of " + count(mapped, "material"));
  add_if(out, plates, count(plates, "zone-plate texture"));
  add_if(out, checkers, count(checkers, "checker texture"));
}

void add_tessellated(std::vector<std::string>& out, const Geometry& g) {
  add_if(out, g.spheres.size(), count(g.spheres.size(), "sphere") + " (tessellated)");
  add_if(out, g.cylinders.size(), count(g.cylinders.size(), "cylinder or cone", "s") + " (tessellated)");
  add_if(out, g.disks.size(), count(g.disks.size(), "disk") + " (tessellated)");
}

std::vector<std::string> nff_losses(const Scene& scene) {
  std::vector<std::string> out;
  std::size_t not_point = 0, spots = 0, falloff = 0;
  for (const Light& l : scene.lights) {
    not_point += l.kind != Light::Kind::kPoint && l.kind != Light::Kind::kSpot ? 1 : 0;
    spots += l.kind == Light::Kind::kSpot ? 1 : 0;
    falloff += l.falloff ? 1 : 0;
  }
  add_if(out, not_point, count(not_point, "directional or area light") + " (as point lights)");
  add_if(out, spots, "cone of " + count(spots, "spot light"));
  add_if(out, falloff, "falloff of " + count(falloff, "light"));
  const auto& ms = scene.materials;
  const std::size_t emitting = count_if(ms, [](const Material& m) { return nonzero(m.emission); });
  add_if(out, emitting, "emission of " + count(emitting, "material"));
  add_texture_losses(out, scene, false);
  // NFF's Ks weights both the highlight and the mirror ray; a scene that weights them apart
  // gets the larger for both.
  const std::size_t split = count_if(ms, [](const Material& m) { return m.ks != m.reflectivity; });
  add_if(out, split, "separate highlight and mirror weights of " + count(split, "material"));
  const std::size_t no_fresnel = count_if(ms, [](const Material& m) { return !m.fresnel; });
  add_if(out, no_fresnel, "fresnel off in " + count(no_fresnel, "material"));
  // The NFF reader sets depth 5, the SPD testing procedure's.
  const RenderSettings& s = scene.settings;
  add_settings(out, s, [&](std::string_view name) {
    return name == "size" || name == "background" || (name == "depth" && s.max_depth == 5);
  });
  add_if(out, scene.geometry.disks.size(), count(scene.geometry.disks.size(), "disk") + " (as 32-gons)");
  add_if(out, scene.geometry.triangle_uvs.size(), "texture coordinates");
  return out;
}

std::vector<std::string> mesh_losses(const Scene& scene, bool obj, bool fitted_view) {
  std::vector<std::string> out;
  if (!fitted_view) {
    out.emplace_back("camera");
    add_if(out, scene.lights.size(), count(scene.lights.size(), "light"));
  }
  const auto& ms = scene.materials;
  if (obj) {
    // MTL has illum 3 (mirror colour Ks) but no separate mirror weight, and no Fresnel switch.
    const std::size_t split =
        count_if(ms, [](const Material& m) { return m.reflectivity > 0.f && m.reflectivity != m.ks; });
    add_if(out, split, "mirror weight of " + count(split, "material"));
    const std::size_t no_fresnel = count_if(ms, [](const Material& m) { return !m.fresnel; });
    add_if(out, no_fresnel, "fresnel off in " + count(no_fresnel, "material"));
    add_texture_losses(out, scene, false);
  } else {
    // A bare mesh's one material is the loader's stand-in, not something the source said.
    const std::size_t used = used_materials(scene);
    add_if(out, fitted_view && used <= 1 ? 0 : used, count(used, "material"));
    add_if(out, scene.objects.size() > 1 ? scene.objects.size() : 0, count(scene.objects.size(), "object"));
  }
  // A bare mesh's settings (its background) are the loader's too.
  if (!fitted_view) add_settings(out, scene.settings, [](std::string_view) { return false; });
  add_tessellated(out, scene.geometry);
  return out;
}

}  // namespace

std::vector<std::string> format_losses(const Scene& scene, std::string_view extension, bool fitted_view) {
  std::vector<std::string> out;
  if (extension == ".nff") {
    out = nff_losses(scene);
  } else if (extension == ".obj") {
    out = mesh_losses(scene, true, fitted_view);
  } else if (extension == ".ply") {
    out = mesh_losses(scene, false, fitted_view);
  } else {
    add_texture_losses(out, scene, true);
  }
  // The environment: only a scene file carries it (an image as a PFM beside it).
  if (scene.environment && extension != ".json") out.emplace_back("environment");
  return out;
}

std::string losses_message(const std::string& output, const std::vector<std::string>& losses) {
  if (losses.empty()) return {};
  std::string out = output + " cannot carry: ";
  for (std::size_t i = 0; i < losses.size(); ++i) out += (i ? ", " : "") + losses[i];
  return out;
}

}  // namespace raylab
