// Watertight ray-triangle intersection: Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013. The triangle is transformed into a space where the ray starts
// at the origin and points along +z; the hit test is then three 2-D edge functions, evaluated
// so that neighbouring triangles agree exactly on their shared edge.
#include "freezeray/triangle_intersection.hpp"

#include <cmath>
#include <utility>

namespace freezeray {

RayShear::RayShear(const Vec3& d) {
    // kz: the dimension where the direction is largest; kx, ky the other two, swapped if needed
    // to keep the winding of the transformed triangle (paper, section 3).
    const Vec3 a = glm::abs(d);
    kz = (a.x > a.y) ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0.0f) std::swap(kx, ky);
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0f / d[kz];
}

}  // namespace freezeray
