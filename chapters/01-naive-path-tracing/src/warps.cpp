// Sampling warps and their densities (Pharr, Jakob and Humphreys, PBR 3rd ed., section 13.6).
#include "freezeray/ch01/warps.hpp"

#include "freezeray/error.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch01 {

// BOOK(sample-uniform-hemisphere)
// Inverting the CDF of the uniform density 1/(2 pi) over the hemisphere gives cos(theta) = u.x,
// uniform in [0, 1], and phi = 2 pi u.y (PBR 3rd ed., eq. 13.6).
Vec3 sample_uniform_hemisphere(const Vec2& u) {
    // EXERCISE(ch01/uniform-hemisphere): map u in [0,1)^2 to a direction on the hemisphere z >= 0 with constant density, by the inversion method of book chapter 01, "Choosing directions uniformly"
    const float cos_theta = u.x;
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    const float phi = 2.0f * Pi * u.y;
    return spherical_direction(sin_theta, cos_theta, phi);
    // END EXERCISE
}

float uniform_hemisphere_pdf() { return Inv2Pi; }
// END BOOK

// cos(theta) uniform in [-1, 1] covers the sphere with constant density 1/(4 pi).
Vec3 sample_uniform_sphere(const Vec2& u) {
    const float cos_theta = 1.0f - 2.0f * u.x;
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    const float phi = 2.0f * Pi * u.y;
    return spherical_direction(sin_theta, cos_theta, phi);
}

float uniform_sphere_pdf() { return Inv4Pi; }

// Heitz, "A Low-Distortion Map Between Triangle and Square", 2019: no square root, and
// neighbouring points of the square stay neighbours on the triangle.
Vec2 sample_uniform_triangle(const Vec2& u) {
    float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2.0f;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2.0f;
        b0 = u.x - b1;
    }
    return Vec2(b0, b1);
}

}  // namespace freezeray::ch01
