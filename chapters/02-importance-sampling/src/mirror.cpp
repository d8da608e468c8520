// The perfect mirror.
#include "freezeray/ch02/mirror.hpp"

#include <cmath>

namespace freezeray::ch02 {

// The mirror direction of wo about +z is (-x, -y, z). The delta lobe f = R delta(wi - wr) /
// |cos theta_i| makes the rendering equation's integral R L(wr); sample() returns it as
// f = R / |cos theta_i| with pdf 1, so that the weight f |cos| / pdf is R (PBR 4th ed., section 9.3).
std::optional<BSDFSample> MirrorBSDF::sample(const Vec3& wo, const Vec2& /*u*/, float /*u_lobe*/) const {
    if (wo.z == 0.0f) return std::nullopt;
    BSDFSample s;
    s.wi = Vec3(-wo.x, -wo.y, wo.z);
    s.f = reflectance_ / std::abs(s.wi.z);
    s.pdf = 1.0f;
    s.flags = BSDF_Reflection | BSDF_Specular;
    return s;
}

}  // namespace freezeray::ch02
