// Light at a smooth interface: where it goes (the laws of reflection and refraction) and how
// much of it is reflected (the Fresnel equations), for dielectrics and for conductors.
#pragma once

#include "freezeray/math.hpp"

#include <optional>
#include <string>
#include <vector>

namespace freezeray::ch02 {

// --- Directions -----------------------------------------------------------------------------------

// The mirror direction of w about the normal n (both unit vectors, any side): 2 (w.n) n - w.
inline Vec3 reflect(const Vec3& w, const Vec3& n) { return 2.0f * glm::dot(w, n) * n - w; }

// The direction refracted from w through an interface with normal n and relative index eta =
// n_other_side / n_side_of_n; nothing on total internal reflection. w and n may be on opposite
// sides (then the interface is seen from below and eta is inverted). Snell's law in vector form
// (Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., 2023, section 9.3).
std::optional<Vec3> refract(const Vec3& w, const Vec3& n, float eta);

// --- Dielectrics ------------------------------------------------------------------------------------

// The unpolarised reflectance of a smooth dielectric interface, the mean of the s- and
// p-polarised reflectances. eta = n_transmitted / n_incident when cos_theta_i > 0; for
// cos_theta_i < 0 the light arrives from inside and eta is inverted. Returns 1 on total internal
// reflection.
float fresnel_dielectric(float cos_theta_i, float eta);

// The reflectances of the two polarisations separately (same conventions): s (perpendicular to
// the plane of incidence) and p (parallel to it). r_p vanishes at Brewster's angle, atan(eta).
float fresnel_dielectric_s_polarised(float cos_theta_i, float eta);
float fresnel_dielectric_p_polarised(float cos_theta_i, float eta);

// The diffuse (hemispherical) reflectance of a smooth dielectric interface lit uniformly from
// the side whose relative index is eta: the cosine-weighted mean of fresnel_dielectric over the
// hemisphere, 2 integral of F(cos, eta) cos d cos over [0, 1]. In closed form (see the source).
float fresnel_diffuse_reflectance(float eta);

// --- Conductors -------------------------------------------------------------------------------------

// The unpolarised reflectance of a smooth conductor with complex index eta + i k, per colour
// channel, for light arriving at cos_theta_i (its absolute value is used: a metal reflects the
// same on both sides).
Spectrum fresnel_conductor(float cos_theta_i, const Spectrum& eta, const Spectrum& k);

// Measured optical constants of a metal, sampled at 650, 550 and 450 nm for R, G and B.
struct ConductorPreset {
    const char* name;
    Spectrum eta;
    Spectrum k;
};

// The preset named "gold", "silver", "copper" or "aluminium" ("aluminum" too); nullptr if unknown.
const ConductorPreset* find_conductor_preset(const std::string& name);

// The names find_conductor_preset knows (without aliases).
std::vector<std::string> conductor_preset_names();

}  // namespace freezeray::ch02
