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
Lanes safe_sqrt(Lanes x) { return sqrt(max(x, splat(0.0f))); }
float safe_acos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }

// Cones are widened by this angle wherever they are computed, so that rounding never leaves a
// direction out (a light left out would be a light never sampled where it shines: bias).
constexpr float ConeSlack = 1e-4f;

// cos(max(0, a - b)) and sin(max(0, a - b)) from the sines and cosines of a and b in [0, pi].
Lanes cos_sub_clamped(Lanes sin_a, Lanes cos_a, Lanes sin_b, Lanes cos_b) {
    return select(cos_a > cos_b, splat(1.0f), cos_a * cos_b + sin_a * sin_b);  // a < b: the difference is clamped to 0
}
Lanes sin_sub_clamped(Lanes sin_a, Lanes cos_a, Lanes sin_b, Lanes cos_b) {
    return select(cos_a > cos_b, splat(0.0f), sin_a * cos_b - cos_a * sin_b);
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

void LightClusterGroup::set(int lane, const LightBounds& bounds) {
    const Vec3 centre = (bounds.box.min + bounds.box.max) * 0.5f;
    const Vec3 half_diagonal = bounds.box.diagonal() * 0.5f;
    const float r_squared = glm::dot(half_diagonal, half_diagonal);
    centre_x[lane] = centre.x;
    centre_y[lane] = centre.y;
    centre_z[lane] = centre.z;
    radius_squared[lane] = r_squared;
    radius[lane] = std::sqrt(r_squared);
    inverse_radius_squared[lane] = 1.0f / r_squared;
    w_x[lane] = bounds.w.x;
    w_y[lane] = bounds.w.y;
    w_z[lane] = bounds.w.z;
    cos_theta_o[lane] = bounds.cos_theta_o;
    sin_theta_o[lane] = safe_sqrt(1.0f - bounds.cos_theta_o * bounds.cos_theta_o);
    cos_theta_e[lane] = bounds.cos_theta_e;
    phi[lane] = bounds.phi;
}

// BOOK(light-importance)
FREEZERAY_ALSO_FOR_AVX2 Lanes importance(const LightClusterGroup& c, const ShadingPoint& point) {
    // EXERCISE(ch10/cluster-importance): the bound on what each cluster of the group can send to the point, book chapter 10, "The importance of a cluster", as importance's comment in light_bounds.hpp states it, lane by lane; never 0 where some light of a cluster may reach the point, 0 in a lane without a cluster
    const Lanes dx = point.position.x - c.centre_x, dy = point.position.y - c.centre_y, dz = point.position.z - c.centre_z;
    const Lanes distance_squared = dx * dx + dy * dy + dz * dz;
    const Lanes distance = sqrt(distance_squared);
    // 1 / d as d / d^2: the division need not wait for the square root.
    const Lanes inverse_distance_squared = 1.0f / distance_squared;
    const Lanes inverse_distance = select(distance > 0.0f, distance * inverse_distance_squared, splat(0.0f));

    // theta_b: the half-angle of the box's bounding sphere seen from the point (the whole
    // sphere of directions from inside it: cos_b = -1). Its sine and cosine, like the others
    // below, are lengths times 1 / d: one division for all.
    const LaneMask outside = distance_squared > c.radius_squared;
    const Lanes sin_b = select(outside, c.radius * inverse_distance, splat(0.0f));
    const Lanes cos_b = select(outside, safe_sqrt(distance_squared - c.radius_squared) * inverse_distance, splat(-1.0f));

    // cos theta': theta' is the smallest angle between an emitter's normal and a direction to the
    // point: theta_w from the cone's axis, less theta_o (the normals' spread), less theta_b (the
    // cluster's extent), at least 0. Each step is computed in every lane, clamped or not, and
    // the clamps are selects. A cluster that emits every way (theta_o = pi) needs no case of its
    // own: theta_w - theta_o is never above 0, so cos theta' comes out 1.
    const Lanes w_dot = c.w_x * dx + c.w_y * dy + c.w_z * dz;
    const Lanes cos_w = w_dot * inverse_distance;
    const Lanes sin_w = safe_sqrt(distance_squared - w_dot * w_dot) * inverse_distance;
    const Lanes cos_x = cos_sub_clamped(sin_w, cos_w, c.sin_theta_o, c.cos_theta_o);
    const Lanes sin_x = sin_sub_clamped(sin_w, cos_w, c.sin_theta_o, c.cos_theta_o);
    const Lanes cos_p = cos_sub_clamped(sin_x, cos_x, sin_b, cos_b);
    // Outside every emitter's cone by more than rounding: no light of the cluster reaches here.
    const LaneMask reaches = (cos_p >= c.cos_theta_e - ConeSlack) & (c.phi > 0.0f);

    // phi / d^2, with d at least the radius (a point inside gets phi / r^2), at most the largest
    // float (a point on a point light); the cosines below only make it smaller.
    const Lanes inverse_squared = select(outside, inverse_distance_squared, c.inverse_radius_squared);
    const Lanes power = min(c.phi * inverse_squared, splat(std::numeric_limits<float>::max()));
    Lanes result = power * max(cos_p, splat(0.0f));
    if (point.normal != Vec3(0.0f)) {
        // The largest |cos| at the point's normal over the cluster; never 0, since the sampler
        // does not know whether the surface lets light through from behind or at grazing angles.
        const Lanes n_dot = point.normal.x * dx + point.normal.y * dy + point.normal.z * dz;
        const Lanes cos_i = max(n_dot, -n_dot) * inverse_distance;
        const Lanes sin_i = safe_sqrt(distance_squared - n_dot * n_dot) * inverse_distance;
        result *= max(cos_sub_clamped(sin_i, cos_i, sin_b, cos_b), splat(ReceiverFloor));
    }
    // A cluster's emitter cosine may be 0 at the edge of its cone: keep it samplable there.
    return select(reaches, max(result, splat(std::numeric_limits<float>::min())), splat(0.0f));
    // END EXERCISE
}
// END BOOK

// BOOK(lobe-factor)
FREEZERAY_ALSO_FOR_AVX2 Lanes lobe_factor(const LightClusterGroup& c, const ShadingPoint& point) {
    // The direction from the point to each cluster's centre, and the half-angle theta_b of the
    // cluster's bounding sphere seen from the point, as in importance().
    const Lanes dx = c.centre_x - point.position.x, dy = c.centre_y - point.position.y, dz = c.centre_z - point.position.z;
    const Lanes distance_squared = dx * dx + dy * dy + dz * dz;
    const Lanes inverse_distance = select(distance_squared > 0.0f, 1.0f / sqrt(distance_squared), splat(0.0f));
    const LaneMask outside = distance_squared > c.radius_squared;
    const Lanes sin_b = select(outside, c.radius * inverse_distance, splat(0.0f));
    const Lanes cos_b = select(outside, safe_sqrt(distance_squared - c.radius_squared) * inverse_distance, splat(-1.0f));
    // psi: the angle between the lobe's axis and the centre; psi - theta_b, at least 0, the
    // smallest angle between the axis and a direction into the sphere.
    const Lanes a_dot = point.lobe_axis.x * dx + point.lobe_axis.y * dy + point.lobe_axis.z * dz;
    const Lanes cos_a = a_dot * inverse_distance;
    const Lanes sin_a = safe_sqrt(distance_squared - a_dot * a_dot) * inverse_distance;
    const Lanes cos_p = cos_sub_clamped(sin_a, cos_a, sin_b, cos_b);
    // A direction psi' from the mirror direction has its half vector psi' / 2 from the normal (in
    // the plane of incidence; elsewhere about so). D(theta) / D(0) = 1 / (cos^2 theta +
    // sin^2 theta / alpha^2)^2 for Trowbridge-Reitz, with cos^2 theta = (1 + cos psi') / 2 and
    // sin^2 theta = (1 - cos psi') / 2 (Walter et al. 2007, equation 33).
    const float inverse_alpha_squared = 1.0f / (point.lobe_alpha * point.lobe_alpha);
    const Lanes x = ((1.0f + cos_p) + (1.0f - cos_p) * inverse_alpha_squared) * 0.5f;
    return 1.0f / (x * x);
}
// END BOOK

float importance(const LightBounds& bounds, const ShadingPoint& point) {
    LightClusterGroup group;
    group.set(0, bounds);
    return importance(group, point)[0];
}

}  // namespace freezeray::ch10
