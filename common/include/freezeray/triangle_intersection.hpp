// Watertight ray-triangle intersection.
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/ray.hpp"

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

// Intersects a ray with triangle (p0, p1, p2) in the interval (0, tmax). Watertight: a ray
// through a shared edge or vertex hits exactly one of the triangles that share it, never none
// (Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013).
std::optional<TriangleHit> intersect_triangle(const Ray& ray, const RayShear& shear, const Vec3& p0,
                                              const Vec3& p1, const Vec3& p2);

}  // namespace freezeray
