// What a light, or a cluster of lights, can send towards a point, bounded: where it is, which
// way it emits and how much (book chapter 10; Conty Estevez and Kulla, "Importance Sampling of
// Many Lights with Adaptive Tree Splitting", 2018, section 4; Pharr, Jakob and Humphreys,
// "Physically Based Rendering", 4th edition, 2023, section 12.6.3).
#pragma once

#include "freezeray/light.hpp"
#include "freezeray/light_sampler.hpp"
#include "freezeray/math.hpp"

#include <array>
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

// BOOK(light-cluster)
// A cluster's bounds as importance() reads them: the centre and the squared radius of the box's
// bounding sphere, and the sine of theta_o beside its cosine, computed once per node when the
// tree is built rather than at every shading point.
struct LightCluster {
    Vec3 centre{0.0f};
    float radius_squared = 0.0f;
    Vec3 w{0.0f, 0.0f, 1.0f};
    float phi = 0.0f;
    float cos_theta_o = 1.0f, sin_theta_o = 0.0f;
    float cos_theta_e = 1.0f;

    LightCluster() = default;
    explicit LightCluster(const LightBounds& bounds);
};
// END BOOK

// The least factor importance() gives a point's normal: a light in the plane of the surface
// keeps a chance (the sampler does not know what the surface's BSDF does at grazing angles).
inline constexpr float ReceiverFloor = 1e-3f;

// How much light the cluster can send to `point` at most, up to a constant factor common to
// every cluster: phi times the largest cosine at the emitters towards the point, times the
// largest |cos| at the point's normal (when it has one), over the squared distance. It is 0 only
// where no light of the cluster reaches the point at all; otherwise it is at least the smallest
// positive float, so that every light that may shine on the point can be chosen there.
float importance(const LightCluster& cluster, const ShadingPoint& point);
inline float importance(const LightBounds& bounds, const ShadingPoint& point) { return importance(LightCluster(bounds), point); }

// The probabilities of going to each of two clusters from `point`: in proportion to their
// importance; {-1, -1} when neither can send light there.
std::array<float, 2> child_probabilities(const LightCluster& first, const LightCluster& second, const ShadingPoint& point);

}  // namespace freezeray::ch10
