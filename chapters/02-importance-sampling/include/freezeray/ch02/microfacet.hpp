// The Trowbridge–Reitz (GGX) microfacet distribution: a rough surface seen as a field of tiny
// mirrors whose normals wm are spread around the macroscopic normal +z. Rough conductors,
// rough dielectrics and rough plastic are built on it.
//
// Trowbridge and Reitz, "Average irregularity representation of a rough surface for ray
// reflection", JOSA 65(5), 1975; Walter et al., "Microfacet Models for Refraction through Rough
// Surfaces", EGSR 2007 (who named it GGX); Heitz, "Understanding the Masking-Shadowing Function
// in Microfacet-Based BRDFs", JCGT 3(2), 2014; Heitz, "Sampling the GGX Distribution of Visible
// Normals", JCGT 7(4), 2018.
#pragma once

#include "freezeray/math.hpp"

#include <cmath>

namespace freezeray::ch02 {

// The microfacet normal that reflects wo into wi: the half vector (wo + wi) / |wo + wi|, turned to
// the upper side (microfacet normals always face up; the surface is seen from either side).
// Zero when it is undefined (wi = -wo).
inline Vec3 reflection_half_vector(const Vec3& wo, const Vec3& wi) {
    const Vec3 h = wo + wi;
    const float length2 = glm::dot(h, h);
    if (length2 == 0.0f) return Vec3(0.0f);
    const Vec3 wm = h / std::sqrt(length2);
    return wm.z < 0.0f ? -wm : wm;
}

class TrowbridgeReitz {
public:
    // alpha_x, alpha_y: the roughness along the x and y axes of the shading frame (equal: isotropic).
    TrowbridgeReitz(float alpha_x, float alpha_y);

    // The perceptually uniform roughness parameter of a scene mapped to alpha: alpha = roughness^2
    // (Burley, "Physically-Based Shading at Disney", SIGGRAPH 2012 course notes).
    static float roughness_to_alpha(float roughness);

    // True when the surface is so smooth that a delta lobe is the better model: max(alpha) < 1e-3.
    bool effectively_smooth() const;

    float alpha_x() const { return alpha_x_; }
    float alpha_y() const { return alpha_y_; }

    // The density of microfacet normals wm per unit solid angle, projected: it integrates
    // D(wm) cos(theta_m) over the hemisphere to 1. Zero below the surface.
    float D(const Vec3& wm) const;

    // Smith's auxiliary function Lambda(w): the mean occluded slope area seen from w.
    float lambda(const Vec3& w) const;

    // The fraction of microfacets visible from w (Smith masking), 1 / (1 + Lambda(w)).
    float G1(const Vec3& w) const;

    // The fraction visible from both wo and wi: the height-correlated Smith masking-shadowing
    // function 1 / (1 + Lambda(wo) + Lambda(wi)).
    float G(const Vec3& wo, const Vec3& wi) const;

    // The distribution of normals visible from w: G1(w) max(0, w.wm) D(wm) / cos theta(w). For w
    // below the surface it is the distribution seen from -w (the surface looked at from inside).
    float D(const Vec3& w, const Vec3& wm) const;

    // The density with which sample_visible_normal(w, u) returns wm: D(w, wm).
    float pdf(const Vec3& w, const Vec3& wm) const;

    // A microfacet normal (on the upper hemisphere) distributed as D(w, wm), from two uniform
    // numbers u.
    Vec3 sample_visible_normal(const Vec3& w, const Vec2& u) const;

private:
    float alpha_x_;
    float alpha_y_;
};

}  // namespace freezeray::ch02
