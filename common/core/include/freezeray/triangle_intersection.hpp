// Watertight ray-triangle intersection.
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/ray.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace freezeray {

struct TriangleHit {
    float t;
    float b0, b1, b2;  // barycentric coordinates, b0 + b1 + b2 = 1
};

// Precomputed per ray: the axis permutation and shear of the watertight test.
struct RayShear {
    int kx, ky, kz;
    float sx, sy, sz;
    explicit RayShear(const Vec3& direction);
};

namespace triangle_detail {

// gamma(n) = n eps / (1 - n eps): the bound on the relative error of n floating-point operations
// (Higham 2002; PBR 3rd ed., eq. 3.8), eps = half the machine epsilon (as in accelerator.cpp).
constexpr float gamma_bound(int n) {
    constexpr float eps = std::numeric_limits<float>::epsilon() * 0.5f;
    return (n * eps) / (1.0f - n * eps);
}

inline float max_abs(float a, float b, float c) { return std::max({std::abs(a), std::abs(b), std::abs(c)}); }

// Tie-breaking for a ray exactly on an edge (edge function exactly zero): the edge belongs to
// only one of the two triangles sharing it, as with the "top-left" rule of rasterisers. The two
// triangles traverse the shared edge in opposite directions, so exactly one of them owns it; a
// hit exactly on a shared edge or vertex is therefore reported once, never twice or not at all.
inline bool owns_edge(float from_x, float from_y, float to_x, float to_y) {
    const float dx = to_x - from_x;
    const float dy = to_y - from_y;
    return dy > 0.0f || (dy == 0.0f && dx > 0.0f);
}

}  // namespace triangle_detail

// Intersects a ray with triangle (p0, p1, p2) in the interval (0, tmax). Watertight: a ray
// through a shared edge or vertex hits exactly one of the triangles that share it, never none
// (Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013).
// Defined here, inline, since every accelerator calls it once per candidate triangle: in the
// caller's loop the compiler can keep the ray and its shear in registers.
inline std::optional<TriangleHit> intersect_triangle(const Ray& ray, const RayShear& shear, const Vec3& p0,
                                              const Vec3& p1, const Vec3& p2) {
    // Vertices relative to the ray origin, sheared so the ray runs along +z (paper, figure 2).
    const Vec3 a = p0 - ray.origin;
    const Vec3 b = p1 - ray.origin;
    const Vec3 c = p2 - ray.origin;
    const float ax = a[shear.kx] - shear.sx * a[shear.kz];
    const float ay = a[shear.ky] - shear.sy * a[shear.kz];
    const float bx = b[shear.kx] - shear.sx * b[shear.kz];
    const float by = b[shear.ky] - shear.sy * b[shear.kz];
    const float cx = c[shear.kx] - shear.sx * c[shear.kz];
    const float cy = c[shear.ky] - shear.sy * c[shear.kz];

    // Scaled barycentric coordinates: the 2-D edge functions at the origin.
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;

    // On an edge in single precision: recompute in double so that the sign is exact.
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = static_cast<float>(static_cast<double>(cx) * by - static_cast<double>(cy) * bx);
        v = static_cast<float>(static_cast<double>(ax) * cy - static_cast<double>(ay) * cx);
        w = static_cast<float>(static_cast<double>(bx) * ay - static_cast<double>(by) * ax);
    }

    // Inside means all three have the same sign (either winding is accepted).
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return std::nullopt;
    const float det = u + v + w;
    if (det == 0.0f) return std::nullopt;  // degenerate, or the ray lies in the triangle's plane

    // Exactly on an edge: only the owning triangle reports the hit. u is the edge b->c, v the
    // edge c->a, w the edge a->b.
    if (u == 0.0f && !triangle_detail::owns_edge(bx, by, cx, cy)) return std::nullopt;
    if (v == 0.0f && !triangle_detail::owns_edge(cx, cy, ax, ay)) return std::nullopt;
    if (w == 0.0f && !triangle_detail::owns_edge(ax, ay, bx, by)) return std::nullopt;

    // Scaled hit distance, compared with the interval before dividing (paper, section 3.3).
    const float az = shear.sz * a[shear.kz];
    const float bz = shear.sz * b[shear.kz];
    const float cz = shear.sz * c[shear.kz];
    const float t_scaled = u * az + v * bz + w * cz;
    if (det < 0.0f && (t_scaled >= 0.0f || t_scaled < ray.tmax * det)) return std::nullopt;
    if (det > 0.0f && (t_scaled <= 0.0f || t_scaled > ray.tmax * det)) return std::nullopt;

    const float inverse_det = 1.0f / det;
    const float t = t_scaled * inverse_det;
    if (!(t > 0.0f) || !(t < ray.tmax)) return std::nullopt;

    // A t within its own rounding error of zero may be a ray leaving this very triangle: reject
    // it (PBR 3rd ed., section 3.9.6, "conservative ray-triangle t"). Offsetting spawned origins
    // (ray.cpp) is the other half of that method and is not enough alone: a point exactly on an
    // axis-aligned triangle has zero error, so its offset is zero, and a ray leaving it then hit
    // its own triangle at t ~ 1e-7 in 9 % of directions (tests/stability, "rays spawned from the
    // Cornell box at scales 1e-4, 1 and 1e4 never hit their own triangle").
    const float max_z = triangle_detail::max_abs(az, bz, cz);
    const float delta_z = triangle_detail::gamma_bound(3) * max_z;
    const float max_x = triangle_detail::max_abs(ax, bx, cx);
    const float max_y = triangle_detail::max_abs(ay, by, cy);
    const float delta_x = triangle_detail::gamma_bound(5) * (max_x + max_z);
    const float delta_y = triangle_detail::gamma_bound(5) * (max_y + max_z);
    const float delta_e = 2.0f * (triangle_detail::gamma_bound(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    const float max_e = triangle_detail::max_abs(u, v, w);
    const float delta_t =
        3.0f * (triangle_detail::gamma_bound(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * std::abs(inverse_det);
    if (t <= delta_t) return std::nullopt;
    return TriangleHit{t, u * inverse_det, v * inverse_det, w * inverse_det};
}

}  // namespace freezeray
