#pragma once
/// \file
/// Whitted/Phong materials, the procedural checker and zone-plate textures and image textures.

#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include "raylab/core/vec3.h"
#include "raylab/scene/metals.h"
#include "raylab/scene/texture_image.h"

namespace raylab {

/// A variation of the diffuse colour over the surface. `kNone` uses the material's colour;
/// `kChecker` alternates it with `color2`; `kImage` multiplies it by `image` at the surface's
/// texture coordinates (as glTF's baseColorFactor x baseColorTexture and MTL's Kd x map_Kd do);
/// `kZonePlate` is the analytic antialiasing test chart described at `zone_plate`.
struct Texture {
  /// Which variation applies.
  enum class Kind { kNone, kChecker, kImage, kZonePlate };

  /// No texture.
  Texture() = default;
  /// A procedural texture from its kind, second colour and cell size. (A constructor rather than
  /// aggregate initialisation, so that `{kind, color2, scale}` stays valid and warning-free now
  /// that the struct has an image member too.)
  Texture(Kind kind_, Color color2_, float scale_ = 1.f) : kind(kind_), color2(color2_), scale(scale_) {}
  /// An image texture.
  static Texture from_image(std::shared_ptr<const TextureImage> image_) {
    Texture t;
    t.kind = Kind::kImage;
    t.image = std::move(image_);
    return t;
  }
  /// A zone plate: with r the distance of (u, v) from `center_`, the value
  /// s = 0.5 + 0.5 cos(pi k r^2) blends from `color2_` (s = 0) to the material colour (s = 1)
  /// inside the disc r <= `radius_`; outside it the colour is the flat mean of the two. The
  /// phase pi k r^2 has the derivative 2 pi k r, so the local frequency is k r cycles per unit
  /// of (u, v): it grows linearly from the centre and reaches k * radius at the rim.
  static Texture zone_plate(Color color2_, Vec2 center_, float k_, float radius_) {
    Texture t(Kind::kZonePlate, color2_);
    t.zone_center = center_;
    t.zone_k = k_;
    t.zone_radius = radius_;
    return t;
  }

  Kind kind = Kind::kNone;         ///< which variation applies
  Color color2{0.1f, 0.1f, 0.1f};  ///< the checker's (or zone plate's) second colour (the first is Material::color)
  float scale = 1.f;               ///< checker cell size in surface-coordinate units
  Vec2 zone_center;                ///< kZonePlate: centre of the rings in (u, v)
  float zone_k = 0.f;              ///< kZonePlate: chirp rate k; local frequency k r cycles per (u, v) unit
  float zone_radius = 0.f;         ///< kZonePlate: radius of the disc holding the rings (flat mean outside)
  /// kImage: the texels (shared: many materials and scene copies may use one decoded image).
  /// See texture_image.h for the (u, v) convention.
  std::shared_ptr<const TextureImage> image;
};

/// Images that vary a material over its surface beyond its colour, each read at the surface
/// coordinates (u, v) with TextureImage's convention. All are optional. The data maps
/// (metallic-roughness, transmission, normal, bump) hold linear values, as glTF 2.0 prescribes;
/// the emission map is a colour. The path integrator reads them all; the Whitted integrator sees
/// the normal and bump maps (through surface_at's shading normal) and nothing else.
struct MaterialMaps {
  /// glTF's metallicRoughnessTexture: green multiplies `roughness`, blue `metallic`.
  std::shared_ptr<const TextureImage> metallic_roughness;
  /// Multiplies `emission` (glTF's emissiveTexture, MTL's map_Ke).
  std::shared_ptr<const TextureImage> emission;
  /// Red multiplies `transmission` (KHR_materials_transmission's transmissionTexture).
  std::shared_ptr<const TextureImage> transmission;
  /// A tangent-space normal map in glTF's (OpenGL's) convention: a texel c gives the normal
  /// 2c - 1 in the frame (+x along increasing u, +y along increasing v, +z the surface normal).
  /// glTF's normalTexture, MTL's norm (and a map_Bump that holds normals, docs/rendering.md).
  std::shared_ptr<const TextureImage> normal;
  float normal_scale = 1.f;  ///< multiplies the x and y of the normal map (glTF's normalTexture.scale)
  /// A height map (MTL's map_Bump or bump): its red channel times `bump_scale` is a displacement
  /// along the normal, in scene units, that tilts the shading normal without moving the surface.
  std::shared_ptr<const TextureImage> bump;
  float bump_scale = 1.f;  ///< displacement of a texel value of 1 (MTL's -bm)

  /// True when the normal or bump map changes the shading normal.
  bool changes_normal() const { return normal != nullptr || bump != nullptr; }
  /// True when no map is set.
  bool empty() const { return !metallic_roughness && !emission && !transmission && !normal && !bump; }
};

/// The scattering model a material names, as its source gave it. The Whitted integrator shades
/// every model through the Phong members below; the path integrator maps each onto its BSDFs
/// (render/material_bsdf.h, docs/rendering.md), Phong included.
enum class MaterialModel : std::uint8_t {
  kPhong = 0,          ///< Whitted's: kd, ks, shininess, reflectivity, transmittance, ior (NFF, MTL, old files)
  kDiffuse,            ///< Lambertian: `color`
  kConductor,          ///< metal: complex index `conductor_eta`, `conductor_k`, times `color`; `roughness`
  kDielectric,         ///< glass: `ior`, `roughness`; `color` tints the transmitted light
  kPlastic,            ///< diffuse `color` under a dielectric coat of index `ior` and `roughness`
  kMetallicRoughness,  ///< glTF 2.0: `color` (base), `metallic`, `roughness`, `ior`, `transmission`
};

/// Surface response in the spirit of Whitted (1980) and the NFF `f` line: a Phong-lit colour
/// plus perfect mirror reflection and perfect refraction, and the physically based models of
/// MaterialModel. Defaults give a matte grey. Every member has a default, so that a designated
/// initialiser names only what differs from it.
struct Material {
  std::string name;               ///< for messages and scene files
  Color color{0.7f, 0.7f, 0.7f};  ///< base (diffuse) colour
  float kd = 1.f;                 ///< diffuse weight
  float ks = 0.f;                 ///< Phong specular weight (highlights from lights)
  float shininess = 32.f;         ///< Phong exponent
  float reflectivity = 0.f;       ///< weight of the mirror-reflected ray (NFF's Ks doubles as this)
  float transmittance = 0.f;      ///< weight of the refracted ray
  float ior = 1.f;                ///< index of refraction (inside / outside)
  Color emission{0.f, 0.f, 0.f};  ///< light emitted towards the viewer, added unshadowed
  Texture texture{};              ///< optional variation of `color` (checker or image)
  bool fresnel = true;            ///< weight reflection/refraction of dielectrics by Fresnel

  // The physically based models (the Whitted integrator reads none of these).

  MaterialModel model = MaterialModel::kPhong;  ///< which model the members describe
  /// Perceptual roughness in [0, 1] (glTF's): the GGX alpha is its square; 0 is perfectly smooth.
  float roughness = 0.f;
  float metallic = 0.f;                ///< kMetallicRoughness: 0 dielectric, 1 metal (fractions mix the two)
  float transmission = 0.f;            ///< kMetallicRoughness: KHR_materials_transmission's factor
  Color conductor_eta = kGoldIor.eta;  ///< kConductor: real part of the index (default gold)
  Color conductor_k = kGoldIor.k;      ///< kConductor: imaginary part (default gold)
  /// The path integrator's emitted radiance is emission * emission_strength (glTF's
  /// KHR_materials_emissive_strength, Blender's Strength). Whitted adds `emission` alone: its
  /// image is a display colour, not radiance, and a strength would blow it out.
  float emission_strength = 1.f;
  MaterialMaps maps{};  ///< optional images varying the parameters above over the surface
};

/// A material's physically based parameters at one point of its surface, its textures applied.
struct MaterialPoint {
  Color base;                ///< diffuse_color() there
  float roughness = 0.f;     ///< `roughness` times the metallic-roughness map's green
  float metallic = 0.f;      ///< `metallic` times the map's blue
  float transmission = 0.f;  ///< `transmission` times the transmission map's red
};

/// The parameters of `m` at surface coordinates (u, v).
MaterialPoint material_at(const Material& m, float u, float v);

/// The radiance the path integrator takes `m` to emit at surface coordinates (u, v):
/// emission x emission_strength, times the emission map there.
Color emitted_radiance(const Material& m, float u, float v);

/// The diffuse colour of `m` at surface coordinates (u, v): the material colour, varied by its
/// texture. An image texture without an image leaves the colour as it is.
Color diffuse_color(const Material& m, float u, float v);

/// True when shading with `m` reads the surface coordinates (u, v): a texture or a map varies it
/// over the surface. Where it is false, diffuse_color, material_at and emitted_radiance give the
/// same at every (u, v).
bool reads_surface_coordinates(const Material& m);

}  // namespace raylab
