// Cosine-weighted hemisphere sampling and the Lambertian BSDF that uses it.
#include "freezeray/ch02/cosine_lambertian.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch02 {

// Shirley and Chiu 1997: the square [-1,1]^2 is cut into four triangles by its diagonals; each
// triangle's concentric squares map to concentric circles, its other coordinate to the angle
// within a quarter of the disk. Area ratios are preserved, so the density stays 1 / pi
// (PBR 3rd ed., section 13.6.2).
Vec2 sample_concentric_disk(const Vec2& u) {
    const Vec2 offset = 2.0f * u - Vec2(1.0f);
    if (offset.x == 0.0f && offset.y == 0.0f) return Vec2(0.0f);
    float r, theta;
    if (std::abs(offset.x) > std::abs(offset.y)) {
        r = offset.x;
        theta = (Pi / 4.0f) * (offset.y / offset.x);
    } else {
        r = offset.y;
        theta = Pi / 2.0f - (Pi / 4.0f) * (offset.x / offset.y);
    }
    return r * Vec2(std::cos(theta), std::sin(theta));
}

// BOOK(cosine-hemisphere)
// Malley's method: points uniform on the unit disk, lifted vertically onto the hemisphere, have
// density cos(theta) / pi per solid angle, because the projection onto the disk multiplies solid
// angle by cos(theta) (PBR 3rd ed., section 13.6.3).
Vec3 sample_cosine_hemisphere(const Vec2& u) {
    // EXERCISE(ch02/cosine-hemisphere): map u in [0,1)^2 to a direction on the hemisphere z >= 0 whose density is proportional to cos(theta), as book chapter 02, "Lambertian, cosine-weighted", derives it
    const Vec2 d = sample_concentric_disk(u);
    const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return Vec3(d.x, d.y, z);
    // END EXERCISE
}

float cosine_hemisphere_pdf(float cos_theta) { return std::max(cos_theta, 0.0f) * InvPi; }
// END BOOK

std::optional<BSDFSample> CosineLambertianBSDF::sample(const Vec3& wo, const Vec2& u, float /*u_lobe*/) const {
    if (wo.z == 0.0f) return std::nullopt;
    Vec3 wi = sample_cosine_hemisphere(u);
    if (wo.z < 0.0f) wi.z = -wi.z;          // reflect on the side wo is on, as chapter 01's Lambertian does
    if (wi.z == 0.0f) return std::nullopt;  // on the horizon: pdf 0
    BSDFSample s;
    s.wi = wi;
    s.f = eval(wo, wi);
    s.pdf = cosine_hemisphere_pdf(std::abs(wi.z));
    s.flags = BSDF_Reflection | BSDF_Diffuse;
    return s;
}

float CosineLambertianBSDF::pdf(const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere(wo, wi) ? cosine_hemisphere_pdf(std::abs(wi.z)) : 0.0f;
}

}  // namespace freezeray::ch02
