#pragma once
/// \file
/// The laws of optics every integrator shares: Fresnel reflectance of dielectrics and
/// conductors, and Snell's law of refraction. One implementation each, called by Whitted's
/// mirror and glass rays and by the BSDFs of the path integrator alike.

#include "raylab/core/vec3.h"
#include "raylab/scene/metals.h"

namespace raylab {

/// Fresnel reflectance of the two linear polarisations, which the unpolarised reflectance
/// averages; kept apart so that each can be checked against published figures.
struct FresnelTerms {
  float s = 0.f;  ///< perpendicular (senkrecht, TE) polarisation
  float p = 0.f;  ///< parallel (TM) polarisation; 0 at Brewster's angle
};

/// The s and p reflectances of a ray at cosine `cos_i` (clamped to [0, 1]) going from index
/// `eta_i` into `eta_t`; both 1 beyond the critical angle (total internal reflection).
FresnelTerms fresnel_dielectric_sp(float cos_i, float eta_i, float eta_t);

/// Fresnel reflectance of an unpolarised ray at cosine `cos_i` (> 0) going from index `eta_i`
/// into `eta_t`: the mean of the parallel and perpendicular terms; 1 for total internal
/// reflection.
float fresnel_dielectric(float cos_i, float eta_i, float eta_t);

/// Cosine-weighted hemispherical mean of fresnel_dielectric(cos, 1, eta), the fraction of
/// diffuse light arriving from the side of index 1 that an interface of relative index `eta`
/// (> 0) reflects. Closed form for eta > 1 (the integral done analytically, as in the
/// subsurface-scattering literature); for eta < 1 (light leaving a denser medium) from
/// reciprocity, Fdr(eta) = 1 - eta^2 (1 - Fdr(1 / eta)). 0 for eta = 1.
float fresnel_diffuse_reflectance(float eta);

/// Exact Fresnel reflectance of an unpolarised ray at cosine `cos_i` (clamped to [0, 1])
/// meeting a conductor of complex index eta + i k, per channel. With k = 0 and eta > 1 it equals
/// fresnel_dielectric(cos_i, 1, eta); at normal incidence ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2).
Color fresnel_conductor(float cos_i, const ConductorIor& ior);

/// Refracts unit direction `d` through unit normal `n` (facing against `d`) with relative index
/// eta = eta_i / eta_t; returns false on total internal reflection.
bool refract(Vec3 d, Vec3 n, float eta, Vec3& out);

}  // namespace raylab
