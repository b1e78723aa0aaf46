#pragma once
/// \file
/// Whitted/Phong materials and the procedural checker texture.

#include <string>

#include "raylab/core/vec3.h"

namespace raylab {

/// A procedural texture for the diffuse colour. `kNone` uses the material's colour.
struct Texture {
  enum class Kind { kNone, kChecker } kind = Kind::kNone;
  Color color2{0.1f, 0.1f, 0.1f};  ///< the checker's second colour (the first is Material::color)
  float scale = 1.f;               ///< checker cell size in surface-coordinate units
};

/// Surface response in the spirit of Whitted (1980) and the NFF `f` line: a Phong-lit colour
/// plus perfect mirror reflection and perfect refraction. Defaults give a matte grey.
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
  Texture texture;                ///< optional procedural variation of `color`
  bool fresnel = true;            ///< weight reflection/refraction of dielectrics by Fresnel
};

/// The diffuse colour of `m` at surface coordinates (u, v).
Color diffuse_color(const Material& m, float u, float v);

}  // namespace raylab
