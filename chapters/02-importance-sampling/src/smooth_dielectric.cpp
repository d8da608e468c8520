// The smooth dielectric (PBR 4th ed., section 9.5).
#include "freezeray/ch02/smooth_dielectric.hpp"

#include "freezeray/ch02/fresnel.hpp"

#include <cmath>

namespace freezeray::ch02 {

// BOOK(smooth-dielectric-sample)
// Reflection with probability F and refraction with probability T = 1 - F: each lobe's weight
// f |cos| / pdf is then 1 (reflection) or 1 / eta'^2 (refraction), where eta' is the index
// of the side of wi over that of wo. The 1 / eta'^2 is how radiance changes across an interface:
// the same power squeezes into a cone of solid angle smaller by eta'^2 (Veach, "Robust Monte Carlo
// Methods for Light Transport Simulation", 1997, section 5.2). This holds for radiance, what a
// camera path carries. Importance, what a light path carries, crosses without that factor;
// chapter 04, which traces light paths, adds the adjoint BSDF that leaves it out.
std::optional<BSDFSample> SmoothDielectricBSDF::sample(const Vec3& wo, const Vec2& /*u*/, float u_lobe) const {
    if (wo.z == 0.0f) return std::nullopt;
    if (eta_ == 1.0f) {
        // Index-matched: there is no interface, light goes straight on with weight 1. The Fresnel
        // equations would give R = 0 only up to rounding (so u_lobe = 0 could still reflect), and
        // below cos theta = 2.4e-4, where 1 - cos^2 rounds to 1, they report total internal
        // reflection (tests/stability, "an index-matched dielectric passes every direction
        // straight through").
        BSDFSample s;
        s.wi = -wo;
        s.f = Spectrum(1.0f / std::abs(wo.z));
        s.pdf = 1.0f;
        s.flags = BSDF_Transmission | BSDF_Specular;
        return s;
    }
    const float R = fresnel_dielectric(wo.z, eta_);  // 1 on total internal reflection
    const float T = 1.0f - R;

    BSDFSample s;
    if (u_lobe < R) {
        s.wi = Vec3(-wo.x, -wo.y, wo.z);
        s.f = Spectrum(R / std::abs(s.wi.z));
        s.pdf = R;
        s.flags = BSDF_Reflection | BSDF_Specular;
        return s;
    }
    const std::optional<Vec3> wi = refract(wo, Vec3(0.0f, 0.0f, 1.0f), eta_);
    if (!wi || wi->z == 0.0f) return std::nullopt;
    const float eta_crossed = wo.z > 0.0f ? eta_ : 1.0f / eta_;  // n(wi side) / n(wo side)
    s.wi = *wi;
    s.f = Spectrum(T / std::abs(wi->z) / (eta_crossed * eta_crossed));
    s.pdf = T;
    s.flags = BSDF_Transmission | BSDF_Specular;
    s.eta = eta_crossed;
    return s;
}
// END BOOK

std::uint32_t SmoothDielectricBSDF::flags() const {
    if (eta_ == 1.0f) return BSDF_Transmission | BSDF_Specular;  // nothing is ever reflected
    return BSDF_Reflection | BSDF_Transmission | BSDF_Specular;
}

}  // namespace freezeray::ch02
