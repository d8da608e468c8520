// Plastic: a diffuse base under a smooth or rough dielectric coating (the model of Mitsuba 0.6's
// plastic and roughplastic, Jakob 2014; see the header).
#include "freezeray/ch02/plastic.hpp"

#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/ch02/fresnel.hpp"

#include <cmath>

namespace freezeray::ch02 {

// Light that enters the coating reaches the base, and what the base scatters up is partly
// reflected back down by the coating's underside (the fraction Fdr_inside of diffuse light),
// and partly leaves. Dividing by 1 - Fdr_inside normalises the exit: of light entering with
// transmittance 1 - F(cos i), a diffuse_albedo fraction leaves in total. eta^2 accounts for the
// radiance change on leaving the denser coating. Because 1 - Fdr_outside = eta^2 (1 - Fdr_inside)
// (fresnel.cpp), integrating f cos over wi gives exactly diffuse_albedo (1 - F(cos o)).
PlasticBSDF::PlasticBSDF(const Spectrum& diffuse_albedo, float eta, const TrowbridgeReitz* coating)
    : diffuse_albedo_(diffuse_albedo),
      eta_(eta),
      coating_(coating ? *coating : TrowbridgeReitz(0.0f, 0.0f)),
      smooth_(coating == nullptr || coating->effectively_smooth()),
      diffuse_scale_(InvPi / (eta * eta * (1.0f - fresnel_diffuse_reflectance(1.0f / eta)))) {}

Spectrum PlasticBSDF::eval_diffuse(const Vec3& wo, const Vec3& wi) const {
    const float transmitted_in = 1.0f - fresnel_dielectric(std::abs(wi.z), eta_);
    const float transmitted_out = 1.0f - fresnel_dielectric(std::abs(wo.z), eta_);
    return diffuse_albedo_ * (diffuse_scale_ * transmitted_in * transmitted_out);
}

Spectrum PlasticBSDF::eval(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) return Spectrum(0.0f);
    Spectrum f = eval_diffuse(wo, wi);
    if (!smooth_) {  // the coating's glossy lobe: a rough dielectric's reflection (Walter et al. 2007, eq. 20)
        const Vec3 wm = reflection_half_vector(wo, wi);
        if (wm.z == 0.0f) return f;
        const float F = fresnel_dielectric(std::abs(glm::dot(wo, wm)), eta_);
        f += Spectrum(coating_.D(wm) * coating_.G(wo, wi) * F / (4.0f * std::abs(wo.z * wi.z)));
    }
    return f;
}

// The coating's lobe carries about F(cos o) of the light, the base's (1 - F(cos o)) times its
// albedo: pick the coating's lobe in that proportion (Mitsuba's specularSamplingWeight, with the
// albedo's luminance for the base).
float PlasticBSDF::specular_probability(const Vec3& wo) const {
    const float F = fresnel_dielectric(std::abs(wo.z), eta_);
    const float specular = F;
    const float diffuse = (1.0f - F) * luminance(diffuse_albedo_);
    if (specular + diffuse <= 0.0f) return 1.0f;
    return specular / (specular + diffuse);
}

// BOOK(plastic-sample)
// A mixture of two strategies: the coating's lobe with probability p, the cosine-weighted base
// with probability 1 - p. With a smooth coating the first is a delta lobe (weight F / p); the
// second samples only the diffuse part of f, with density (1 - p) cos / pi. With a rough coating
// both lobes are glossy or diffuse and can produce any wi, so a sample's density is the mixture
// density p pdf_coating + (1 - p) pdf_base, whichever lobe produced it (pdf() below), and f is the
// whole BSDF.
std::optional<BSDFSample> PlasticBSDF::sample(const Vec3& wo, const Vec2& u, float u_lobe) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float p = specular_probability(wo);
    BSDFSample s;
    if (u_lobe < p) {
        if (smooth_) {
            s.wi = Vec3(-wo.x, -wo.y, wo.z);
            s.f = Spectrum(fresnel_dielectric(std::abs(wo.z), eta_) / std::abs(s.wi.z));
            s.pdf = p;
            s.flags = BSDF_Reflection | BSDF_Specular;
            return s;
        }
        s.wi = reflect(wo, coating_.sample_visible_normal(wo, u));
        s.flags = BSDF_Reflection | BSDF_Glossy;
    } else {
        s.wi = sample_cosine_hemisphere(u);
        if (wo.z < 0.0f) s.wi.z = -s.wi.z;
        s.flags = BSDF_Reflection | BSDF_Diffuse;
    }
    if (!same_hemisphere(wo, s.wi)) return std::nullopt;
    s.f = eval(wo, s.wi);
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0.0f) || !is_valid_radiance(s.f)) return std::nullopt;
    return s;
}

float PlasticBSDF::pdf(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) return 0.0f;
    const float p = specular_probability(wo);
    const float base = (1.0f - p) * cosine_hemisphere_pdf(std::abs(wi.z));
    if (smooth_) return base;  // the delta lobe has no density
    const Vec3 wm = reflection_half_vector(wo, wi);
    const float cos_wo_wm = std::abs(glm::dot(wo, wm));
    if (wm.z == 0.0f || cos_wo_wm == 0.0f) return base;
    return p * coating_.pdf(wo, wm) / (4.0f * cos_wo_wm) + base;
}
// END BOOK

std::uint32_t PlasticBSDF::flags() const {
    return BSDF_Reflection | BSDF_Diffuse | (smooth_ ? BSDF_Specular : BSDF_Glossy);
}

}  // namespace freezeray::ch02
