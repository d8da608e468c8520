// The Lambertian BSDF and the diffuse material.
#include "freezeray/ch01/lambertian.hpp"

#include "freezeray/ch01/warps.hpp"

namespace freezeray::ch01 {

// BOOK(lambertian-eval)
// A Lambertian surface scatters equally in all directions: f is constant, and energy
// conservation (the integral of f cos(theta) over the hemisphere is the albedo) makes it
// albedo / pi. It reflects on both sides of the surface, never through it.
Spectrum LambertianBSDF::eval(const Vec3& wo, const Vec3& wi) const {
    // EXERCISE(ch01/lambertian-brdf): the Lambertian BRDF of book chapter 01, "The Lambertian surface": its value for the pair (wo, wi) in the local frame, zero unless both lie on the same side
    if (!same_hemisphere(wo, wi)) return Spectrum(0.0f);
    return albedo_ * InvPi;
    // END EXERCISE
}
// END BOOK

std::optional<BSDFSample> LambertianBSDF::sample(const Vec3& wo, const Vec2& u, float /*u_lobe*/) const {
    if (wo.z == 0.0f) return std::nullopt;
    Vec3 wi = sample_uniform_hemisphere(u);
    if (wo.z < 0.0f) wi.z = -wi.z;  // the side wo is on
    BSDFSample s;
    s.wi = wi;
    s.f = eval(wo, wi);
    s.pdf = uniform_hemisphere_pdf();
    s.flags = BSDF_Reflection | BSDF_Diffuse;
    return s;
}

float LambertianBSDF::pdf(const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere(wo, wi) ? uniform_hemisphere_pdf() : 0.0f;
}

const BSDF* DiffuseMaterial::bsdf(const Hit& /*hit*/, ScratchArena& arena) const {
    return arena.make<LambertianBSDF>(albedo_);
}

}  // namespace freezeray::ch01
