// A rough metal: the microfacet model of Torrance and Sparrow with the GGX distribution, each
// microfacet a smooth conductor.
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/ch02/microfacet.hpp"
#include "freezeray/ch02/specular_conductor.hpp"

namespace freezeray::ch02 {

// f = D(wm) G(wo, wi) F(wo.wm) / (4 |cos theta_o| |cos theta_i|), wm the half vector, on both sides
// of the surface; sampled through the normals visible from wo. When the distribution is
// effectively smooth it is exactly SpecularConductorBSDF.
class RoughConductorBSDF final : public BSDF {
public:
    RoughConductorBSDF(const TrowbridgeReitz& distribution, const Spectrum& eta, const Spectrum& k)
        : distribution_(distribution), eta_(eta), k_(k) {}

    Spectrum eval(const Vec3& wo, const Vec3& wi) const override;
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    std::uint32_t flags() const override;
    // Around the mirror direction of wo, as wide as the distribution's larger alpha.
    std::optional<GlossyLobe> glossy_lobe(const Vec3& wo) const override;

private:
    TrowbridgeReitz distribution_;
    Spectrum eta_;
    Spectrum k_;
};

}  // namespace freezeray::ch02
