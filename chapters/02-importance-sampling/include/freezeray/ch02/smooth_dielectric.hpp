// Smooth glass, water, diamond: a dielectric interface that reflects the Fresnel fraction F of the
// light in the mirror direction and refracts the rest by Snell's law.
#pragma once

#include "freezeray/bsdf.hpp"

namespace freezeray::ch02 {

// eta = n_inside / n_outside, the inside being below the surface (wo.z < 0). Two delta lobes,
// chosen with probabilities F and 1 - F; total internal reflection from inside. eta = 1 is an
// index-matched interface: every ray passes straight through.
class SmoothDielectricBSDF final : public BSDF {
public:
    explicit SmoothDielectricBSDF(float eta) : eta_(eta) {}

    Spectrum eval(const Vec3& /*wo*/, const Vec3& /*wi*/) const override { return Spectrum(0.0f); }
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override;
    float pdf(const Vec3& /*wo*/, const Vec3& /*wi*/) const override { return 0.0f; }
    std::uint32_t flags() const override;

    float eta() const { return eta_; }

private:
    float eta_;
};

}  // namespace freezeray::ch02
