// Frosted glass: a rough dielectric interface whose microfacets each reflect and refract like
// smooth glass (Walter, Marschner, Li and Torrance, "Microfacet Models for Refraction through Rough
// Surfaces", EGSR 2007), with the GGX distribution.
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/ch02/microfacet.hpp"
#include "freezeray/ch02/smooth_dielectric.hpp"

namespace freezeray::ch02 {

// eta = n_inside / n_outside, the inside below the surface. A glossy reflection lobe and a glossy
// transmission lobe, sampled through the normals visible from wo and chosen by the Fresnel
// reflectance of the sampled microfacet. When the distribution is effectively smooth, or eta = 1
// (nothing to scatter off), it is exactly SmoothDielectricBSDF.
class RoughDielectricBSDF final : public BSDF {
public:
    RoughDielectricBSDF(const TrowbridgeReitz& distribution, float eta) : distribution_(distribution), eta_(eta) {}

    Spectrum eval(const Vec3& wo, const Vec3& wi) const override;
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    std::uint32_t flags() const override;

private:
    bool is_smooth() const { return distribution_.effectively_smooth() || eta_ == 1.0f; }

    TrowbridgeReitz distribution_;
    float eta_;
};

}  // namespace freezeray::ch02
