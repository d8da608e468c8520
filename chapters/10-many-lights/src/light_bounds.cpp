// Bounds of lights and clusters of lights, and their importance for a shading point (book
// chapter 10; Conty Estevez and Kulla 2018, section 4.1; pbrt-v4, section 12.6.3).
#include "freezeray/ch10/light_bounds.hpp"

#include "freezeray/ch03/area_light.hpp"
#include "freezeray/ch03/point_light.hpp"
#include "freezeray/ch03/spot_light.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace freezeray::ch10 {

namespace {

float safe_sqrt(float x) { return std::sqrt(std::max(x, 0.0f)); }
float safe_acos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }

// Cones are widened by this angle wherever they are computed, so that rounding never leaves a
// direction out (a light left out would be a light never sampled where it shines: bias).
constexpr float ConeSlack = 1e-4f;

// cos(max(0, a - b)) and sin(max(0, a - b)) from the sines and cosines of a and b in [0, pi].
// Written as selects of values computed either way, which compile to no branch.
float cos_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    const float difference = cos_a * cos_b + sin_a * sin_b;
    return cos_a > cos_b ? 1.0f : difference;  // a < b: the difference is clamped to 0
}
float sin_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    const float difference = sin_a * cos_b - cos_a * sin_b;
    return cos_a > cos_b ? 0.0f : difference;
}

// v turned by `angle` about the unit axis k (Rodrigues' formula).
Vec3 rotate(const Vec3& v, const Vec3& k, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (1.0f - c));
}

}  // namespace

DirectionCone cone_union(const DirectionCone& a, const DirectionCone& b) {
    // Conty Estevez and Kulla 2018, algorithm 1.
    const float theta_a = safe_acos(a.cos_theta), theta_b = safe_acos(b.cos_theta);
    const float theta_d = safe_acos(glm::dot(a.w, b.w));
    if (std::min(theta_d + theta_b, Pi) <= theta_a) return a;  // b lies inside a
    if (std::min(theta_d + theta_a, Pi) <= theta_b) return b;
    const float theta_o = (theta_a + theta_d + theta_b) / 2.0f + ConeSlack;
    if (theta_o >= Pi) return DirectionCone::entire_sphere();
    // The new axis: a's, turned towards b's so that the cone just reaches both far edges.
    const Vec3 axis = glm::cross(a.w, b.w);
    const float axis_length = glm::length(axis);
    if (!(axis_length > 0.0f)) return DirectionCone::entire_sphere();  // opposite axes
    const Vec3 w = glm::normalize(rotate(a.w, axis / axis_length, theta_o - ConeSlack - theta_a));
    return {w, std::cos(theta_o)};
}

std::optional<LightBounds> bounds_of(const Light& light) {
    LightBounds b;
    if (const auto* triangle = dynamic_cast<const ch03::TriangleLight*>(&light)) {
        // One-sided: it emits around its normal, up to the plane of the triangle.
        for (const Vec3& p : triangle->vertices()) b.box.expand(p);
        b.w = triangle->normal();
        b.phi = luminance(triangle->emission()) * triangle->area();
        b.cos_theta_o = 1.0f;
        b.cos_theta_e = std::cos(Pi / 2.0f);
        return b;
    }
    if (const auto* point = dynamic_cast<const ch03::PointLight*>(&light)) {
        b.box.expand(point->position());
        b.phi = luminance(point->intensity());
        b.cos_theta_o = -1.0f;  // every direction
        b.cos_theta_e = std::cos(Pi / 2.0f);
        return b;
    }
    if (const auto* spot = dynamic_cast<const ch03::SpotLight*>(&light)) {
        // Full intensity within the falloff start (theta_o), falling off out to the cone's edge
        // (theta_o + theta_e): pbrt-v4's SpotLight::Bounds.
        b.box.expand(spot->position());
        b.w = spot->axis();
        b.phi = luminance(spot->intensity());
        const float theta_start = safe_acos(spot->cos_falloff_start()), theta_cone = safe_acos(spot->cos_cone());
        b.cos_theta_o = std::cos(theta_start);
        b.cos_theta_e = std::cos(std::max(theta_cone - theta_start, 0.0f));
        return b;
    }
    return std::nullopt;
}

LightBounds bounds_union(const LightBounds& a, const LightBounds& b) {
    if (a.phi == 0.0f) return b;
    if (b.phi == 0.0f) return a;
    LightBounds u;
    u.box = a.box;
    u.box.expand(b.box);
    const DirectionCone cone = cone_union({a.w, a.cos_theta_o}, {b.w, b.cos_theta_o});
    u.w = cone.w;
    u.cos_theta_o = cone.cos_theta;
    u.cos_theta_e = std::min(a.cos_theta_e, b.cos_theta_e);
    u.phi = a.phi + b.phi;
    return u;
}

LightCluster::LightCluster(const LightBounds& bounds)
    : centre((bounds.box.min + bounds.box.max) * 0.5f),
      radius_squared(glm::dot(bounds.box.diagonal() * 0.5f, bounds.box.diagonal() * 0.5f)),
      w(bounds.w),
      phi(bounds.phi),
      cos_theta_o(bounds.cos_theta_o),
      sin_theta_o(safe_sqrt(1.0f - bounds.cos_theta_o * bounds.cos_theta_o)),
      cos_theta_e(bounds.cos_theta_e) {}

// BOOK(light-importance)
float importance(const LightCluster& cluster, const ShadingPoint& point) {
    // EXERCISE(ch10/cluster-importance): the bound on what the cluster can send to the point, book chapter 10, "The importance of a cluster", as importance's comment in light_bounds.hpp states it; never 0 where some light of the cluster may reach the point
    if (cluster.phi <= 0.0f) return 0.0f;
    const Vec3 to_point = point.position - cluster.centre;
    const float distance_squared = glm::dot(to_point, to_point);
    const float inverse_distance = distance_squared > 0.0f ? 1.0f / std::sqrt(distance_squared) : 0.0f;

    // theta_b: the half-angle of the box's bounding sphere seen from the point (the whole
    // sphere of directions from inside it: cos_b = -1).
    const bool outside = distance_squared > cluster.radius_squared;
    const float sin_b_squared = outside ? cluster.radius_squared / distance_squared : 0.0f;
    const float sin_b = std::sqrt(sin_b_squared);
    const float cos_b = outside ? safe_sqrt(1.0f - sin_b_squared) : -1.0f;

    // cos theta': theta' is the smallest angle between an emitter's normal and a direction to the
    // point: theta_w from the cone's axis, less theta_o (the normals' spread), less theta_b (the
    // cluster's extent), at least 0. Computed whether or not a step is clamped, and chosen at the
    // end: the walk meets both cases at random, and a mispredicted branch costs more than the
    // arithmetic.
    // sin_w from the squares, sqrt(d^2 - (w . d)^2) / d, so that its square root need not wait
    // for cos_w.
    const float w_dot = glm::dot(cluster.w, to_point);
    const float cos_w = w_dot * inverse_distance;
    const float sin_w = safe_sqrt(distance_squared - w_dot * w_dot) * inverse_distance;
    const float cos_x = cos_sub_clamped(sin_w, cos_w, cluster.sin_theta_o, cluster.cos_theta_o);
    const float sin_x = sin_sub_clamped(sin_w, cos_w, cluster.sin_theta_o, cluster.cos_theta_o);
    const float cos_p = cluster.cos_theta_o > -1.0f ? cos_sub_clamped(sin_x, cos_x, sin_b, cos_b) : 1.0f;
    // Outside every emitter's cone by more than rounding: no light of the cluster reaches here.
    if (cos_p < cluster.cos_theta_e - ConeSlack) return 0.0f;

    // phi / d^2 first: its division need not wait for the cosines.
    float result = cluster.phi / std::max(distance_squared, cluster.radius_squared) * std::max(cos_p, 0.0f);
    if (point.normal != Vec3(0.0f)) {
        // The largest |cos| at the point's normal over the cluster; never 0, since the sampler
        // does not know whether the surface lets light through from behind or at grazing angles.
        const float n_dot = std::abs(glm::dot(to_point, point.normal));
        const float cos_i = n_dot * inverse_distance;
        const float sin_i = safe_sqrt(distance_squared - n_dot * n_dot) * inverse_distance;
        result *= std::max(cos_sub_clamped(sin_i, cos_i, sin_b, cos_b), ReceiverFloor);
    }
    // A cluster's emitter cosine may be 0 at the edge of its cone: keep it samplable there.
    return std::clamp(result, std::numeric_limits<float>::min(), std::numeric_limits<float>::max());
    // END EXERCISE
}
// END BOOK

// BOOK(child-probabilities)
std::array<float, 2> child_probabilities(const LightCluster& first, const LightCluster& second, const ShadingPoint& point) {
    // Halved, so that their sum stays finite when both are as large as the largest float.
    const float a = 0.5f * importance(first, point), b = 0.5f * importance(second, point);
    const float sum = a + b;
    if (!(sum > 0.0f)) return {-1.0f, -1.0f};
    return {a / sum, b / sum};
}
// END BOOK

}  // namespace freezeray::ch10
