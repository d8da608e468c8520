// The rough dielectric after Walter et al. 2007, arranged as pbrt-v4's DielectricBxDF (PBR 4th ed.,
// section 9.7). Equation numbers are Walter et al.'s.
#include "freezeray/ch02/rough_dielectric.hpp"

#include "freezeray/ch02/fresnel.hpp"

#include <cmath>

namespace freezeray::ch02 {

namespace {

// The pair (wo, wi) seen as one microfacet event: its normal wm (on the upper side), whether it
// is a reflection, and eta' = n(wi side) / n(wo side). Invalid for pairs no microfacet produces.
struct MicrofacetEvent {
    bool valid = false;
    bool reflection = false;
    Vec3 wm{0.0f};
    float eta_crossed = 1.0f;
};

// The generalized half vector (eqs. 13 and 16): wo + wi for a reflection, wo + eta' wi for a
// refraction, both pointing along the microfacet normal, which is then turned to the upper side.
// Pairs where wo or wi would be behind that microfacet are not microfacet events.
MicrofacetEvent microfacet_event(const Vec3& wo, const Vec3& wi, float eta) {
    MicrofacetEvent event;
    const float cos_theta_o = wo.z;
    const float cos_theta_i = wi.z;
    // Also when the product underflows (both cosines below about 1e-19): the sign test below would
    // take a reflection for a refraction, and eval divide 0 by 0 (tests/stability, "every BSDF
    // gives finite, non-negative values at grazing angles"). Such pairs scatter nothing.
    if (cos_theta_o * cos_theta_i == 0.0f) return event;
    event.reflection = cos_theta_o * cos_theta_i > 0.0f;
    event.eta_crossed = event.reflection ? 1.0f : (cos_theta_o > 0.0f ? eta : 1.0f / eta);
    Vec3 wm = wo + event.eta_crossed * wi;
    const float length2 = glm::dot(wm, wm);
    if (length2 == 0.0f) return event;
    wm /= std::sqrt(length2);
    if (wm.z < 0.0f) wm = -wm;
    // Both directions must be on the side of the microfacet their macro side says.
    if (glm::dot(wm, wi) * cos_theta_i < 0.0f || glm::dot(wm, wo) * cos_theta_o < 0.0f) return event;
    event.wm = wm;
    event.valid = true;
    return event;
}

// The density of wi = refract(wo, wm) per solid angle of wi, given the density of wm (eq. 17):
// d wm / d wi = |wi.wm| / (wi.wm + wo.wm / eta')^2.
float refraction_jacobian(const Vec3& wo, const Vec3& wi, const Vec3& wm, float eta_crossed) {
    const float denominator = glm::dot(wi, wm) + glm::dot(wo, wm) / eta_crossed;
    return std::abs(glm::dot(wi, wm)) / (denominator * denominator);
}

}  // namespace

// Reflection (eq. 20): D G F / (4 |cos o| |cos i|). Refraction (eq. 21, written with eta' = the
// index of wi's side over wo's):
//     D G (1 - F) |wi.wm| |wo.wm| / (|cos i| |cos o| (wi.wm + wo.wm / eta')^2) / eta'^2,
// where the last 1 / eta'^2 is the radiance scaling (smooth_dielectric.cpp says why, and why
// light paths in chapter 04 leave it out).
Spectrum RoughDielectricBSDF::eval(const Vec3& wo, const Vec3& wi) const {
    if (is_smooth()) return Spectrum(0.0f);
    const MicrofacetEvent event = microfacet_event(wo, wi, eta_);
    if (!event.valid) return Spectrum(0.0f);
    const Vec3& wm = event.wm;
    const float F = fresnel_dielectric(glm::dot(wo, wm), eta_);
    const float DG = distribution_.D(wm) * distribution_.G(wo, wi);
    const float cos_product = std::abs(wo.z * wi.z);
    if (event.reflection) return Spectrum(DG * F / (4.0f * cos_product));
    const float eta2 = event.eta_crossed * event.eta_crossed;
    const float jacobian = refraction_jacobian(wo, wi, wm, event.eta_crossed);
    return Spectrum(DG * (1.0f - F) * jacobian * std::abs(glm::dot(wo, wm)) / cos_product / eta2);
}

// Sample a normal visible from wo, then reflect with probability F(wo.wm) or refract: the density
// of wi is D(wo, wm) times the Jacobian of the chosen event (eqs. 14 and 17) times its probability.
std::optional<BSDFSample> RoughDielectricBSDF::sample(const Vec3& wo, const Vec2& u, float u_lobe) const {
    if (is_smooth()) return SmoothDielectricBSDF(eta_).sample(wo, u, u_lobe);
    if (wo.z == 0.0f) return std::nullopt;
    const float eta = eta_;
    const Vec3 wm = distribution_.sample_visible_normal(wo, u);
    const float cos_wo_wm = glm::dot(wo, wm);
    if (cos_wo_wm == 0.0f) return std::nullopt;
    const float R = fresnel_dielectric(cos_wo_wm, eta);
    const float T = 1.0f - R;
    const float D_visible = distribution_.pdf(wo, wm);

    BSDFSample s;
    if (u_lobe < R) {
        s.wi = reflect(wo, wm);
        if (!same_hemisphere(wo, s.wi)) return std::nullopt;
        s.pdf = D_visible / (4.0f * std::abs(cos_wo_wm)) * R;
        s.f = Spectrum(distribution_.D(wm) * distribution_.G(wo, s.wi) * R / (4.0f * std::abs(wo.z * s.wi.z)));
        s.flags = BSDF_Reflection | BSDF_Glossy;
    } else {
        const std::optional<Vec3> wi = refract(wo, wm, eta);
        if (!wi || same_hemisphere(wo, *wi) || wi->z == 0.0f) return std::nullopt;
        s.wi = *wi;
        s.eta = cos_wo_wm > 0.0f ? eta : 1.0f / eta;
        const float jacobian = refraction_jacobian(wo, s.wi, wm, s.eta);
        s.pdf = D_visible * jacobian * T;
        s.f = Spectrum(distribution_.D(wm) * distribution_.G(wo, s.wi) * T * jacobian * std::abs(cos_wo_wm) /
                       std::abs(wo.z * s.wi.z) / (s.eta * s.eta));
        s.flags = BSDF_Transmission | BSDF_Glossy;
    }
    if (!(s.pdf > 0.0f) || !is_valid_radiance(s.f)) return std::nullopt;
    return s;
}

float RoughDielectricBSDF::pdf(const Vec3& wo, const Vec3& wi) const {
    if (is_smooth()) return 0.0f;
    const MicrofacetEvent event = microfacet_event(wo, wi, eta_);
    if (!event.valid) return 0.0f;
    const Vec3& wm = event.wm;
    const float R = fresnel_dielectric(glm::dot(wo, wm), eta_);
    const float D_visible = distribution_.pdf(wo, wm);
    if (event.reflection) return D_visible / (4.0f * std::abs(glm::dot(wo, wm))) * R;
    return D_visible * refraction_jacobian(wo, wi, wm, event.eta_crossed) * (1.0f - R);
}

std::uint32_t RoughDielectricBSDF::flags() const {
    if (is_smooth()) return SmoothDielectricBSDF(eta_).flags();
    return BSDF_Reflection | BSDF_Transmission | BSDF_Glossy;
}

}  // namespace freezeray::ch02
