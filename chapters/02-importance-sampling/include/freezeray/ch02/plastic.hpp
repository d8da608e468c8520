// Plastic, varnished wood, glazed ceramic: a diffuse base under a clear dielectric coating. The
// coating reflects the Fresnel fraction of the light as a specular (smooth coating) or glossy
// (rough coating) highlight; what it lets through is scattered by the base, and leaves through the
// coating again, diffusely.
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/ch02/microfacet.hpp"

namespace freezeray::ch02 {

// The model of Mitsuba 0.6's "plastic" (Jakob, Mitsuba 0.6 documentation, 2014, section 8.2,
// plugins plastic and roughplastic), with its default linear treatment of the base:
//     f = f_coating + diffuse_albedo (1 - F(cos o)) (1 - F(cos i)) / (pi eta^2 (1 - Fdr_inside)),
// F the coating's Fresnel reflectance, Fdr_inside its diffuse reflectance seen from inside.
// The directional albedo is exactly F(cos o) + (1 - F(cos o)) diffuse_albedo for a smooth coating:
// never above 1. A rough coating adds the GGX reflection of a rough dielectric (Walter et al. 2007)
// and keeps the smooth Fresnel factors for the base, where Mitsuba's roughplastic tabulates the
// rough coating's transmittance: an approximation whose albedo can exceed 1 by up to 7e-4 for a
// white base (tests/unit/test_ch02_bsdfs.cpp measures it). eta = n_coating / n_outside.
// coating: the coating's roughness, nullptr (or an effectively smooth distribution) for a smooth
// coating. Reflects on both sides of the surface.
class PlasticBSDF final : public BSDF {
public:
    PlasticBSDF(const Spectrum& diffuse_albedo, float eta, const TrowbridgeReitz* coating);

    Spectrum eval(const Vec3& wo, const Vec3& wi) const override;
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    std::uint32_t flags() const override;

    // The probability with which sample() picks the coating's lobe for this wo.
    float specular_probability(const Vec3& wo) const;

private:
    Spectrum eval_diffuse(const Vec3& wo, const Vec3& wi) const;

    Spectrum diffuse_albedo_;
    float eta_;
    TrowbridgeReitz coating_;
    bool smooth_;
    float diffuse_scale_;  // 1 / (pi eta^2 (1 - Fdr_inside))
};

}  // namespace freezeray::ch02
