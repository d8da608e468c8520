// Robust spawned ray origins (Pharr, Jakob and Humphreys, PBR 3rd ed., section 3.9.5).
#include "freezeray/ray.hpp"

#include <cmath>

namespace freezeray {

Vec3 offset_ray_origin(const Vec3& point, const Vec3& point_error, const Vec3& geometric_normal,
                       const Vec3& direction) {
    // Distance along the normal that clears the error box around the point (PBR eq. 3.14).
    const float d = glm::dot(glm::abs(geometric_normal), point_error);
    Vec3 offset = d * geometric_normal;
    if (glm::dot(direction, geometric_normal) < 0.0f) offset = -offset;
    Vec3 origin = point + offset;
    // Round away from the point so the rounding of the addition cannot pull it back inside.
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f)
            origin[i] = std::nextafter(origin[i], std::numeric_limits<float>::infinity());
        else if (offset[i] < 0.0f)
            origin[i] = std::nextafter(origin[i], -std::numeric_limits<float>::infinity());
    }
    return origin;
}

}  // namespace freezeray
