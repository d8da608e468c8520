// A smooth metal: a mirror whose reflectance is given by the Fresnel equations of a conductor,
// so that it changes colour and brightens towards grazing angles.
#pragma once

#include "freezeray/bsdf.hpp"

namespace freezeray::ch02 {

// Specular reflection with the conductor Fresnel reflectance of the complex index eta + i k (per
// colour channel; see fresnel.hpp for measured metals), on both sides of the surface.
class SpecularConductorBSDF final : public BSDF {
public:
    SpecularConductorBSDF(const Spectrum& eta, const Spectrum& k) : eta_(eta), k_(k) {}

    Spectrum eval(const Vec3& /*wo*/, const Vec3& /*wi*/) const override { return Spectrum(0.0f); }
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override;
    float pdf(const Vec3& /*wo*/, const Vec3& /*wi*/) const override { return 0.0f; }
    std::uint32_t flags() const override { return BSDF_Reflection | BSDF_Specular; }

    const Spectrum& eta() const { return eta_; }
    const Spectrum& k() const { return k_; }

private:
    Spectrum eta_;
    Spectrum k_;
};

}  // namespace freezeray::ch02
