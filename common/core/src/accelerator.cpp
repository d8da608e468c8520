// Filling in hits, and the brute-force accelerator.
#include "freezeray/accelerator.hpp"

#include "freezeray/triangle_intersection.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace freezeray {

namespace {

// gamma(n) = n eps / (1 - n eps): the bound on the relative error of n floating-point
// operations (Higham 2002; PBR 3rd ed., eq. 3.8), eps = half the machine epsilon.
constexpr float gamma_bound(int n) {
    constexpr float eps = std::numeric_limits<float>::epsilon() * 0.5f;
    return (n * eps) / (1.0f - n * eps);
}

}  // namespace

Hit make_hit(const std::vector<TriangleMesh>& meshes, std::uint32_t mesh_index, std::uint32_t triangle,
             const TriangleHit& th) {
    const TriangleMesh& mesh = meshes[mesh_index];
    const auto& idx = mesh.triangles[triangle];
    const Vec3& p0 = mesh.positions[idx[0]];
    const Vec3& p1 = mesh.positions[idx[1]];
    const Vec3& p2 = mesh.positions[idx[2]];

    Hit hit;
    hit.t = th.t;
    hit.b1 = th.b1;
    hit.b2 = th.b2;
    hit.mesh = mesh_index;
    hit.triangle = triangle;
    hit.material = mesh.face_materials[triangle];
    // Interpolating with barycentrics is more accurate than origin + t d, and its error is
    // bounded by gamma(7) times the sum of the absolute terms (PBR 3rd ed., eq. 3.11).
    hit.position = th.b0 * p0 + th.b1 * p1 + th.b2 * p2;
    hit.position_error = gamma_bound(7) * (glm::abs(th.b0 * p0) + glm::abs(th.b1 * p1) + glm::abs(th.b2 * p2));

    // The cross product is divided by its largest component before normalising: for a triangle
    // whose edges are below about 1e-19 (one ulp of coordinates near 1e-5, say) its squared
    // length underflows to zero, and normalize() gave NaN, which turned every path that met the
    // triangle black (tests/stability, scenes/hard/tiny-triangle). obj_loader.cpp keeps exactly
    // the triangles whose cross product is not zero, so the division is by a non-zero number.
    const Vec3 cross = glm::cross(p1 - p0, p2 - p0);
    hit.geometric_normal = glm::normalize(cross / max_component(glm::abs(cross)));
    if (!mesh.normals.empty()) {
        const Vec3 n = th.b0 * mesh.normals[idx[0]] + th.b1 * mesh.normals[idx[1]] + th.b2 * mesh.normals[idx[2]];
        const float length = glm::length(n);
        hit.shading_normal = length > 0.0f ? n / length : hit.geometric_normal;
        // Shading normals that disagree with the winding are turned to its side: the winding
        // decides which side is the front (for emission), the normals only smooth the shading.
        if (glm::dot(hit.shading_normal, hit.geometric_normal) < 0.0f) hit.shading_normal = -hit.shading_normal;
    } else {
        hit.shading_normal = hit.geometric_normal;
    }
    if (!mesh.uvs.empty()) {
        hit.uv = th.b0 * mesh.uvs[idx[0]] + th.b1 * mesh.uvs[idx[1]] + th.b2 * mesh.uvs[idx[2]];
    } else {
        hit.uv = Vec2(th.b1, th.b2);
    }
    return hit;
}

Ray continue_behind(const Ray& ray, const Hit& hit) {
    Ray next = hit.spawn_ray(ray.direction);
    next.tmax = ray.tmax - glm::dot(next.origin - ray.origin, ray.direction);
    return next;
}

bool Accelerator::occluded_by(const Ray& ray, const TriangleFlags& counted) const {
    // Closest hit after closest hit: each one either counts, or the ray goes on behind it.
    return first_hit_where(*this, ray, [&](const Hit& hit) { return counted[hit.mesh][hit.triangle] != 0; }).has_value();
}

bool clip_ray_to_bounds(const Ray& ray, const Vec3& inverse_direction, const Bounds3& bounds, float& t_enter,
                        float& t_exit) {
    float t0 = 0.0f;
    float t1 = ray.tmax;
    for (int axis = 0; axis < 3; ++axis) {
        float t_near = (bounds.min[axis] - ray.origin[axis]) * inverse_direction[axis];
        float t_far = (bounds.max[axis] - ray.origin[axis]) * inverse_direction[axis];
        if (t_near > t_far) std::swap(t_near, t_far);
        // Widen the far bound by 2 gamma(3) so that rounding never culls a box the ray touches
        // (PBR 3rd ed., section 3.9.2). NaN (0 * inf) comparisons fall through safely.
        t_far *= 1.0f + 2.0f * gamma_bound(3);
        t0 = t_near > t0 ? t_near : t0;
        t1 = t_far < t1 ? t_far : t1;
        if (t0 > t1) return false;
    }
    t_enter = t0;
    t_exit = t1;
    return true;
}

bool ray_intersects_bounds(const Ray& ray, const Vec3& inverse_direction, const Bounds3& bounds) {
    float t_enter = 0.0f, t_exit = 0.0f;
    return clip_ray_to_bounds(ray, inverse_direction, bounds, t_enter, t_exit);
}

void BruteForceAccelerator::build(const std::vector<TriangleMesh>& meshes) {
    meshes_ = &meshes;
    mesh_bounds_.clear();
    for (const TriangleMesh& mesh : meshes) mesh_bounds_.push_back(mesh.bounds());
}

std::optional<Hit> BruteForceAccelerator::intersect(const Ray& ray) const {
    const RayShear shear(ray.direction);
    const Vec3 inverse_direction = 1.0f / ray.direction;
    Ray shortened = ray;
    std::optional<TriangleHit> closest;
    std::uint32_t closest_mesh = 0, closest_triangle = 0;
    for (std::uint32_t m = 0; m < meshes_->size(); ++m) {
        if (!ray_intersects_bounds(shortened, inverse_direction, mesh_bounds_[m])) continue;
        const TriangleMesh& mesh = (*meshes_)[m];
        for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i) {
            const auto& idx = mesh.triangles[i];
            const auto th = intersect_triangle(shortened, shear, mesh.positions[idx[0]], mesh.positions[idx[1]],
                                               mesh.positions[idx[2]]);
            if (th) {
                closest = th;
                closest_mesh = m;
                closest_triangle = i;
                shortened.tmax = th->t;  // later hits must be closer
            }
        }
    }
    if (!closest) return std::nullopt;
    return make_hit(*meshes_, closest_mesh, closest_triangle, *closest);
}

template <typename Counts>
bool BruteForceAccelerator::any_hit(const Ray& ray, Counts&& counts) const {
    const RayShear shear(ray.direction);
    const Vec3 inverse_direction = 1.0f / ray.direction;
    for (std::uint32_t m = 0; m < meshes_->size(); ++m) {
        if (!ray_intersects_bounds(ray, inverse_direction, mesh_bounds_[m])) continue;
        const TriangleMesh& mesh = (*meshes_)[m];
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            if (!counts(m, t)) continue;  // looked through
            const auto& idx = mesh.triangles[t];
            if (intersect_triangle(ray, shear, mesh.positions[idx[0]], mesh.positions[idx[1]], mesh.positions[idx[2]]))
                return true;
        }
    }
    return false;
}

bool BruteForceAccelerator::occluded(const Ray& ray) const {
    return any_hit(ray, [](std::uint32_t, std::size_t) { return true; });
}

bool BruteForceAccelerator::occluded_by(const Ray& ray, const TriangleFlags& counted) const {
    return any_hit(ray, [&](std::uint32_t mesh, std::size_t triangle) { return counted[mesh][triangle] != 0; });
}

}  // namespace freezeray
