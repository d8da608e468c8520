// What a ray found: where, on which triangle, with which normals and texture coordinates.
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/ray.hpp"
#include "freezeray/texture_storage.hpp"

#include <cstdint>

namespace freezeray {

struct Hit {
    float t = 0.0f;
    Vec3 position;
    Vec3 position_error;    // conservative bound on the floating-point error of `position`
    Vec3 geometric_normal;  // unit, from the triangle's winding (counter-clockwise is front)
    Vec3 shading_normal;    // unit, interpolated vertex normal (or the geometric one)
    Vec2 uv;
    // How uv changes from one pixel to the next, when the scene has a camera and textures (zero
    // otherwise): Scene::intersect fills them in (texture_footprint.hpp).
    Vec2 duv_dx{0.0f};
    Vec2 duv_dy{0.0f};
    float b1 = 0.0f, b2 = 0.0f;   // barycentric coordinates of vertices 1 and 2
    std::uint32_t mesh = 0;       // index into Scene::meshes
    std::uint32_t triangle = 0;   // index into that mesh's triangles
    std::uint32_t material = 0;   // index into Scene::materials

    // What a texture is looked up with at this hit.
    TextureLookup texture_lookup() const { return TextureLookup{uv, duv_dx, duv_dy}; }

    // A ray leaving this hit in direction `d`, offset so that it cannot hit this triangle again.
    Ray spawn_ray(const Vec3& d) const {
        return Ray{offset_ray_origin(position, position_error, geometric_normal, d), d};
    }

    // A shadow ray towards `target`, stopping just short of it.
    Ray spawn_ray_to(const Vec3& target) const {
        const Vec3 origin = offset_ray_origin(position, position_error, geometric_normal, target - position);
        const Vec3 d = target - origin;
        const float distance = glm::length(d);
        return Ray{origin, d / distance, distance * (1.0f - 1e-4f)};
    }
};

}  // namespace freezeray
