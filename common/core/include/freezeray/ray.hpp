// Rays, and spawning new rays from a surface without hitting that surface again.
#pragma once

#include "freezeray/math.hpp"

#include <limits>

namespace freezeray {

struct Ray {
    Vec3 origin;
    Vec3 direction;  // unit length
    float tmax = std::numeric_limits<float>::infinity();

    Vec3 at(float t) const { return origin + t * direction; }
};

// Moves a surface point off its surface, along the geometric normal, by just more than the
// floating-point error of the point (pbrt-v3, section 3.9.5 "Robust Spawned Ray Origins"),
// to the side the new direction leaves on. Scale-invariant: the bound grows with the point's
// coordinates, so a scene scaled by 1e4 or 1e-4 behaves the same.
Vec3 offset_ray_origin(const Vec3& point, const Vec3& point_error, const Vec3& geometric_normal,
                       const Vec3& direction);

}  // namespace freezeray
