// The smooth conductor.
#include "freezeray/ch02/specular_conductor.hpp"

#include "freezeray/ch02/fresnel.hpp"

#include <cmath>

namespace freezeray::ch02 {

// As the mirror (mirror.cpp), with the reflectance F(theta_o) of the metal: weight F.
std::optional<BSDFSample> SpecularConductorBSDF::sample(const Vec3& wo, const Vec2& /*u*/, float /*u_lobe*/) const {
    if (wo.z == 0.0f) return std::nullopt;
    BSDFSample s;
    s.wi = Vec3(-wo.x, -wo.y, wo.z);
    s.f = fresnel_conductor(std::abs(wo.z), eta_, k_) / std::abs(s.wi.z);
    s.pdf = 1.0f;
    s.flags = BSDF_Reflection | BSDF_Specular;
    return s;
}

}  // namespace freezeray::ch02
