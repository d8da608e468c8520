// What a light, or a cluster of lights, can send towards a point, bounded: where it is, which
// way it emits and how much (book chapter 10; Conty Estevez and Kulla, "Importance Sampling of
// Many Lights with Adaptive Tree Splitting", 2018, section 4; Pharr, Jakob and Humphreys,
// "Physically Based Rendering", 4th edition, 2023, section 12.6.3).
#pragma once

#include "freezeray/ch10/lanes.hpp"
#include "freezeray/light.hpp"
#include "freezeray/light_sampler.hpp"
#include "freezeray/math.hpp"

#include <optional>

namespace freezeray::ch10 {

// A cone of directions around the unit axis `w`, of half-angle theta with cos theta =
// cos_theta (1: the axis alone, -1: every direction).
struct DirectionCone {
    Vec3 w{0.0f, 0.0f, 1.0f};
    float cos_theta = 1.0f;

    static DirectionCone entire_sphere() { return {Vec3(0.0f, 0.0f, 1.0f), -1.0f}; }
};

// The smallest cone (in the construction of Conty Estevez and Kulla 2018, algorithm 1) holding
// both cones; rounded outwards so that it never leaves out a direction of either.
DirectionCone cone_union(const DirectionCone& a, const DirectionCone& b);

// BOOK(light-bounds)
// The bounds of a cluster of lights. Every light in it lies in `box`; every direction it emits
// in is within theta_o + theta_e of `w` (theta_o bounds the lights' normals or axes around w,
// theta_e how far from its normal a light emits: pi/2 for a one-sided area light). `phi` sums
// what each light sends at most, in units where phi cos / d^2 is an irradiance: radiance times
// area for an area light, intensity for a point or spot light.
struct LightBounds {
    Bounds3 box;
    Vec3 w{0.0f, 0.0f, 1.0f};
    float phi = 0.0f;
    float cos_theta_o = 1.0f;
    float cos_theta_e = 1.0f;
};
// END BOOK

// The bounds of one light: nothing for a light that has no position (environment and directional
// lights, which are chosen beside the tree) or a kind this chapter does not know.
std::optional<LightBounds> bounds_of(const Light& light);

// The bounds of two clusters together.
LightBounds bounds_union(const LightBounds& a, const LightBounds& b);

// BOOK(light-cluster-group)
// The bounds of up to four clusters as importance() reads them, one cluster per lane (structure
// of arrays): the centre and radius of each box's bounding sphere (also squared, and 1 / its
// square: infinite for a point), the cone's axis w, the cosine and sine of theta_o, the cosine of
// theta_e, and phi, which is 0 in a lane that holds no cluster. Computed once per node when the
// tree is built rather than at every shading point.
struct LightClusterGroup {
    Lanes centre_x{}, centre_y{}, centre_z{};
    Lanes radius{}, radius_squared{}, inverse_radius_squared{};
    Lanes w_x{}, w_y{}, w_z{};
    Lanes cos_theta_o{}, sin_theta_o{}, cos_theta_e{};
    Lanes phi{};

    void set(int lane, const LightBounds& bounds);
};
// END BOOK

// The least factor importance() gives a point's normal: a light in the plane of the surface
// keeps a chance (the sampler does not know what the surface's BSDF does at grazing angles).
inline constexpr float ReceiverFloor = 1e-3f;

// How much light each cluster can send to `point` at most, up to a constant factor common to
// every cluster: phi times the largest cosine at the emitters towards the point, times the
// largest |cos| at the point's normal (when it has one), over the squared distance. It is 0 only
// where no light of the cluster reaches the point at all (and in a lane without a cluster);
// otherwise it is at least the smallest positive float, so that every light that may shine on
// the point can be chosen there.
Lanes importance(const LightClusterGroup& clusters, const ShadingPoint& point);

// How much of a glossy lobe (point.lobe_axis, point.lobe_alpha > 0) can look at each cluster of
// the group, relative to the lobe's peak: the Trowbridge-Reitz (GGX) distribution D at the
// half-vector angle of the direction nearest the lobe's axis within the cluster's bounding
// sphere, over D at the axis; 1 where the sphere holds the axis (or the point), never below
// alpha^4. Chapter 10, "The lobe at the point".
Lanes lobe_factor(const LightClusterGroup& clusters, const ShadingPoint& point);

// The importance of one cluster (computed in lane 0 of a group).
float importance(const LightBounds& bounds, const ShadingPoint& point);

}  // namespace freezeray::ch10
