// The laws of reflection and refraction and the Fresnel equations.
// Sources: Born and Wolf, "Principles of Optics", 7th ed., 1999, sections 1.5 (dielectrics) and
// 14.2 (absorbing media); Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., 2023,
// section 9.3 (the same equations in the form used here).
#include "freezeray/ch02/fresnel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

namespace freezeray::ch02 {

std::optional<Vec3> refract(const Vec3& w, const Vec3& n, float eta) {
    Vec3 normal = n;
    float cos_theta_i = glm::dot(normal, w);
    if (cos_theta_i < 0.0f) {  // w is below the interface: look at it from that side
        eta = 1.0f / eta;
        cos_theta_i = -cos_theta_i;
        normal = -normal;
    }
    // Snell's law: sin(theta_t) = sin(theta_i) / eta.
    const float sin2_theta_i = std::max(0.0f, 1.0f - cos_theta_i * cos_theta_i);
    const float sin2_theta_t = sin2_theta_i / (eta * eta);
    if (sin2_theta_t >= 1.0f) return std::nullopt;  // total internal reflection
    const float cos_theta_t = std::sqrt(std::max(0.0f, 1.0f - sin2_theta_t));
    return -w / eta + (cos_theta_i / eta - cos_theta_t) * normal;
}

// BOOK(fresnel-dielectric)
// The Fresnel equations for a smooth interface between two dielectrics (Born and Wolf, section
// 1.5.2): the amplitude reflection coefficients of the two polarisations,
//     r_parallel      = (eta cos_i - cos_t) / (eta cos_i + cos_t),
//     r_perpendicular = (cos_i - eta cos_t) / (cos_i + eta cos_t),
// with cos_t from Snell's law; unpolarised light reflects the mean of their squares.
float fresnel_dielectric(float cos_theta_i, float eta) {
    // EXERCISE(ch02/dielectric-fresnel): the unpolarised Fresnel reflectance of a smooth dielectric, book chapter 02, "Fresnel reflectance": 1 on total internal reflection; cos_theta_i < 0 means the light arrives from inside (the ratio of indices turns over)
    cos_theta_i = std::clamp(cos_theta_i, -1.0f, 1.0f);
    if (cos_theta_i < 0.0f) {
        eta = 1.0f / eta;
        cos_theta_i = -cos_theta_i;
    }
    const float sin2_theta_i = 1.0f - cos_theta_i * cos_theta_i;
    const float sin2_theta_t = sin2_theta_i / (eta * eta);
    if (sin2_theta_t >= 1.0f) return 1.0f;  // total internal reflection
    const float cos_theta_t = std::sqrt(std::max(0.0f, 1.0f - sin2_theta_t));
    const float r_parallel = (eta * cos_theta_i - cos_theta_t) / (eta * cos_theta_i + cos_theta_t);
    const float r_perpendicular = (cos_theta_i - eta * cos_theta_t) / (cos_theta_i + eta * cos_theta_t);
    return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
    // END EXERCISE
}
// END BOOK

namespace {

// The s- and p-polarised reflectances, |r_perpendicular|^2 and |r_parallel|^2.
struct PolarisedReflectance {
    float s = 1.0f;
    float p = 1.0f;
};

PolarisedReflectance polarised_reflectance(float cos_theta_i, float eta) {
    cos_theta_i = std::clamp(cos_theta_i, -1.0f, 1.0f);
    if (cos_theta_i < 0.0f) {
        eta = 1.0f / eta;
        cos_theta_i = -cos_theta_i;
    }
    const float sin2_theta_t = (1.0f - cos_theta_i * cos_theta_i) / (eta * eta);
    if (sin2_theta_t >= 1.0f) return {};  // total internal reflection: both are 1
    const float cos_theta_t = std::sqrt(std::max(0.0f, 1.0f - sin2_theta_t));
    const float r_parallel = (eta * cos_theta_i - cos_theta_t) / (eta * cos_theta_i + cos_theta_t);
    const float r_perpendicular = (cos_theta_i - eta * cos_theta_t) / (cos_theta_i + eta * cos_theta_t);
    return {r_perpendicular * r_perpendicular, r_parallel * r_parallel};
}

// a / b for a non-zero b, written out: the library's complex division is a call to a general
// routine that rescales its operands to survive infinities, and cost a conductor's shading a
// tenth of its time. In double precision, |b|^2 cannot overflow for any b made of floats.
std::complex<double> divide(const std::complex<double>& a, const std::complex<double>& b) {
    const double denominator = b.real() * b.real() + b.imag() * b.imag();
    return {(a.real() * b.real() + a.imag() * b.imag()) / denominator,
            (a.imag() * b.real() - a.real() * b.imag()) / denominator};
}

// |a|^2, written out for the same reason (std::norm may go through std::abs).
double squared_magnitude(const std::complex<double>& a) { return a.real() * a.real() + a.imag() * a.imag(); }

// The unpolarised reflectance of an absorbing medium of complex index eta = n + i k: the same
// equations as for dielectrics with complex cosines (Born and Wolf, section 14.2; PBR 4th ed.,
// section 9.3), in double precision. Only |r|^2 is needed, and |a / b|^2 = |a|^2 / |b|^2.
float fresnel_complex(float cos_theta_i, std::complex<float> eta_float) {
    if (eta_float == std::complex<float>(0.0f)) return 1.0f;  // the limit of a perfect conductor
    const double cos_i = std::clamp(static_cast<double>(cos_theta_i), 0.0, 1.0);
    const std::complex<double> eta(eta_float.real(), eta_float.imag());
    // cos^2(theta_t) = 1 - sin^2(theta_i) / eta^2, written as ((eta^2 - 1) + cos^2(theta_i)) / eta^2:
    // the same number without the cancellation 1 - (1 - cos^2), which rounds cos^2 away at grazing
    // angles. With it, a conductor with eta = 1 and k = 0 (what an MTL Ks of 0 gives) reflected 1e-16
    // everywhere and everything below cos theta = 2.4e-4 (tests/stability, conductor-k0/eta-1.json).
    const std::complex<double> eta2 = eta * eta;
    const std::complex<double> cos_t = std::sqrt(divide((eta2 - 1.0) + cos_i * cos_i, eta2));
    const double r_parallel = squared_magnitude(eta * cos_i - cos_t) / squared_magnitude(eta * cos_i + cos_t);
    const double r_perpendicular = squared_magnitude(cos_i - eta * cos_t) / squared_magnitude(cos_i + eta * cos_t);
    return static_cast<float>(0.5 * (r_parallel + r_perpendicular));
}

// The diffuse reflectance of an interface lit from the optically thinner side (n > 1): the
// integral 2 int_0^1 F(c, n) c dc of the Fresnel equations, in closed form. It agrees with
// numerical quadrature to 1e-8 (tests/unit/test_fresnel.cpp). Computed in double: the terms
// cancel strongly as n approaches 1.
double diffuse_reflectance_from_thinner_side(double n) {
    if (n - 1.0 < 1e-3) return (n - 1.0) / 3.0;  // the first-order limit: r -> 0 as n -> 1
    const double n2 = n * n;
    const double n4 = n2 * n2;
    return 0.5 + (n - 1.0) * (3.0 * n + 1.0) / (6.0 * (n + 1.0) * (n + 1.0)) +
           n2 * (n2 - 1.0) * (n2 - 1.0) / ((n2 + 1.0) * (n2 + 1.0) * (n2 + 1.0)) * std::log((n - 1.0) / (n + 1.0)) -
           2.0 * n * n2 * (n2 + 2.0 * n - 1.0) / ((n2 + 1.0) * (n4 - 1.0)) +
           8.0 * n4 * (n4 + 1.0) / ((n2 + 1.0) * (n4 - 1.0) * (n4 - 1.0)) * std::log(n);
}

}  // namespace

float fresnel_dielectric_s_polarised(float cos_theta_i, float eta) { return polarised_reflectance(cos_theta_i, eta).s; }

float fresnel_dielectric_p_polarised(float cos_theta_i, float eta) { return polarised_reflectance(cos_theta_i, eta).p; }

float fresnel_diffuse_reflectance(float eta) {
    if (eta == 1.0f) return 0.0f;
    if (eta > 1.0f) return static_cast<float>(diffuse_reflectance_from_thinner_side(eta));
    // From the denser side, reciprocity relates the two diffuse transmittances:
    // 1 - r(eta) = eta^2 (1 - r(1 / eta)) (what is not reflected is transmitted, and radiance
    // crossing an interface scales by the squared ratio of the indices).
    const double n = 1.0 / static_cast<double>(eta);
    return static_cast<float>(1.0 - (1.0 - diffuse_reflectance_from_thinner_side(n)) / (n * n));
}

Spectrum fresnel_conductor(float cos_theta_i, const Spectrum& eta, const Spectrum& k) {
    const float cos_theta = std::abs(cos_theta_i);
    Spectrum reflectance;
    for (int c = 0; c < 3; ++c) reflectance[c] = fresnel_complex(cos_theta, std::complex<float>(eta[c], k[c]));
    return reflectance;
}

namespace {

// Optical constants n, k of evaporated metal films at 650, 550 and 450 nm (R, G, B), from
// McPeak et al., "Plasmonic Films Can Easily Be Better: Rules and Recipes", ACS Photonics 2(3),
// 326-333, 2015, as tabulated by refractiveindex.info (database/data-nk/main/{Au,Ag,Cu,Al}/McPeak.yml,
// CC0); all three wavelengths are table entries, no interpolation. Their normal-incidence
// reflectances ((n-1)^2 + k^2) / ((n+1)^2 + k^2) are
//     gold 0.968 0.848 0.390, silver 0.990 0.988 0.980, copper 0.973 0.675 0.582, aluminium 0.904 0.916 0.922.
const std::array<ConductorPreset, 4> conductor_presets{{
    {"gold", Spectrum(0.125499f, 0.323931f, 1.538326f), Spectrum(3.792328f, 2.597158f, 1.910745f)},
    {"silver", Spectrum(0.050913f, 0.043817f, 0.040932f), Spectrum(4.460223f, 3.610114f, 2.675757f)},
    {"copper", Spectrum(0.104232f, 0.797460f, 1.048210f), Spectrum(3.775694f, 2.564204f, 2.413637f)},
    {"aluminium", Spectrum(1.246364f, 0.789405f, 0.489220f), Spectrum(6.852330f, 5.851937f, 4.778319f)},
}};

}  // namespace

const ConductorPreset* find_conductor_preset(const std::string& name) {
    const std::string wanted = name == "aluminum" ? "aluminium" : name;
    for (const ConductorPreset& preset : conductor_presets)
        if (wanted == preset.name) return &preset;
    return nullptr;
}

std::vector<std::string> conductor_preset_names() {
    std::vector<std::string> names;
    for (const ConductorPreset& preset : conductor_presets) names.emplace_back(preset.name);
    return names;
}

}  // namespace freezeray::ch02
