// The perfect mirror: every ray leaves in the mirror direction, with the same colour at every
// angle. Not a physical material (a real metal's reflectance changes towards grazing angles,
// see SpecularConductorBSDF), but the simplest delta lobe, and what MTL files call a mirror.
#pragma once

#include "freezeray/bsdf.hpp"

namespace freezeray::ch02 {

// Specular reflection of `reflectance` at every angle, on both sides of the surface.
class MirrorBSDF final : public BSDF {
public:
    explicit MirrorBSDF(const Spectrum& reflectance) : reflectance_(reflectance) {}

    // A delta lobe: no direction chosen independently of wo can hit it.
    Spectrum eval(const Vec3& /*wo*/, const Vec3& /*wi*/) const override { return Spectrum(0.0f); }
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override;
    float pdf(const Vec3& /*wo*/, const Vec3& /*wi*/) const override { return 0.0f; }
    std::uint32_t flags() const override { return BSDF_Reflection | BSDF_Specular; }

private:
    Spectrum reflectance_;
};

}  // namespace freezeray::ch02
