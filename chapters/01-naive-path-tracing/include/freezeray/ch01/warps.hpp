// Sampling warps: maps from uniform numbers in [0,1)^2 to directions and points, each beside its
// density. Derivations: Pharr, Jakob and Humphreys, "Physically Based Rendering", 3rd ed., 13.6.
#pragma once

#include "freezeray/math.hpp"

namespace freezeray::ch01 {

// Uniform direction on the hemisphere around +z; density 1 / (2 pi) per steradian.
Vec3 sample_uniform_hemisphere(const Vec2& u);
float uniform_hemisphere_pdf();

// Uniform direction on the unit sphere; density 1 / (4 pi) per steradian.
Vec3 sample_uniform_sphere(const Vec2& u);
float uniform_sphere_pdf();

// Uniform point on a triangle, as barycentric coordinates (b0, b1); b2 = 1 - b0 - b1.
// Density 1 / area. (Heitz, "A Low-Distortion Map Between Triangle and Square", 2019.)
Vec2 sample_uniform_triangle(const Vec2& u);

}  // namespace freezeray::ch01
