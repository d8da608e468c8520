// The rough conductor: Torrance and Sparrow, "Theory for Off-Specular Reflection from Roughened
// Surfaces", JOSA 57(9), 1967, in the form of Walter et al. 2007 (eq. 20) with GGX, and sampled as
// in Heitz 2018 (visible normals).
#include "freezeray/ch02/rough_conductor.hpp"

#include "freezeray/ch02/fresnel.hpp"

#include <cmath>

namespace freezeray::ch02 {

Spectrum RoughConductorBSDF::eval(const Vec3& wo, const Vec3& wi) const {
    if (distribution_.effectively_smooth() || !same_hemisphere(wo, wi)) return Spectrum(0.0f);
    const float cos_theta_o = std::abs(wo.z);
    const float cos_theta_i = std::abs(wi.z);
    const Vec3 wm = reflection_half_vector(wo, wi);
    if (wm.z == 0.0f) return Spectrum(0.0f);
    const Spectrum F = fresnel_conductor(std::abs(glm::dot(wo, wm)), eta_, k_);
    return distribution_.D(wm) * distribution_.G(wo, wi) * F / (4.0f * cos_theta_o * cos_theta_i);
}

// Sample a microfacet normal among those visible from wo and reflect wo about it. Changing
// variables from wm to wi = reflect(wo, wm) divides the density by 4 |wo.wm| (Walter et al.
// 2007, eq. 14): pdf = D(wo, wm) / (4 |wo.wm|). Some reflected directions go below the surface
// (the microfacet faces away steeply): those samples fail, and the integral of pdf is below one.
std::optional<BSDFSample> RoughConductorBSDF::sample(const Vec3& wo, const Vec2& u, float u_lobe) const {
    if (distribution_.effectively_smooth()) return SpecularConductorBSDF(eta_, k_).sample(wo, u, u_lobe);
    if (wo.z == 0.0f) return std::nullopt;
    const Vec3 wm = distribution_.sample_visible_normal(wo, u);
    const Vec3 wi = reflect(wo, wm);
    if (!same_hemisphere(wo, wi)) return std::nullopt;
    const float cos_wo_wm = std::abs(glm::dot(wo, wm));
    if (cos_wo_wm == 0.0f) return std::nullopt;

    BSDFSample s;
    s.wi = wi;
    s.pdf = distribution_.pdf(wo, wm) / (4.0f * cos_wo_wm);
    const Spectrum F = fresnel_conductor(cos_wo_wm, eta_, k_);
    s.f = distribution_.D(wm) * distribution_.G(wo, wi) * F / (4.0f * std::abs(wo.z) * std::abs(wi.z));
    s.flags = BSDF_Reflection | BSDF_Glossy;
    if (!(s.pdf > 0.0f) || !is_valid_radiance(s.f)) return std::nullopt;
    return s;
}

float RoughConductorBSDF::pdf(const Vec3& wo, const Vec3& wi) const {
    if (distribution_.effectively_smooth() || !same_hemisphere(wo, wi)) return 0.0f;
    const Vec3 wm = reflection_half_vector(wo, wi);
    if (wm.z == 0.0f) return 0.0f;
    const float cos_wo_wm = std::abs(glm::dot(wo, wm));
    if (cos_wo_wm == 0.0f) return 0.0f;
    return distribution_.pdf(wo, wm) / (4.0f * cos_wo_wm);
}

std::optional<GlossyLobe> RoughConductorBSDF::glossy_lobe(const Vec3& wo) const {
    if (distribution_.effectively_smooth() || wo.z == 0.0f) return std::nullopt;
    return GlossyLobe{Vec3(-wo.x, -wo.y, wo.z), std::max(distribution_.alpha_x(), distribution_.alpha_y())};
}

std::uint32_t RoughConductorBSDF::flags() const {
    return distribution_.effectively_smooth() ? SpecularConductorBSDF(eta_, k_).flags()
                                              : (BSDF_Reflection | BSDF_Glossy);
}

}  // namespace freezeray::ch02
