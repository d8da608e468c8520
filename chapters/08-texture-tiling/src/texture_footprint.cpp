// The footprint of a pixel in texture space.
#include "freezeray/ch08/texture_footprint.hpp"

#include <cmath>

namespace freezeray::ch08 {

namespace {

using DVec3 = glm::dvec3;

}  // namespace

// BOOK(texture-footprint)
void add_texture_footprint(Hit& hit, const TriangleMesh& mesh, const Camera& camera) {
    const DVec3 to_hit = DVec3(hit.position) - DVec3(camera.position());
    const double distance = glm::length(to_hit);
    const DVec3 normal(hit.geometric_normal);
    const double normal_distance = glm::dot(normal, to_hit);  // of the triangle's plane from the pinhole
    if (!(distance > 0.0) || normal_distance == 0.0) {
        hit.duv_dx = hit.duv_dy = Vec2(1.0f);
        return;
    }
    // Two directions across the ray, one towards the image's right (or its up, should the ray run
    // along the right), the other at right angles to both.
    const DVec3 w = to_hit / distance;
    DVec3 across = DVec3(camera.right()) - glm::dot(DVec3(camera.right()), w) * w;
    if (glm::length(across) < 1e-3) across = glm::cross(w, DVec3(camera.forward()));
    const DVec3 e1 = glm::normalize(across);
    const DVec3 e2 = glm::cross(w, e1);

    // The triangle's edges from vertex 0, and the normal equations of
    // dp = d_b1 (p1 - p0) + d_b2 (p2 - p0): their determinant is |edge1 x edge2|^2 > 0.
    const auto& index = mesh.triangles[hit.triangle];
    const DVec3 p0(mesh.positions[index[0]]);
    const DVec3 edge1 = DVec3(mesh.positions[index[1]]) - p0;
    const DVec3 edge2 = DVec3(mesh.positions[index[2]]) - p0;
    const double a11 = glm::dot(edge1, edge1), a12 = glm::dot(edge1, edge2), a22 = glm::dot(edge2, edge2);
    const double determinant = a11 * a22 - a12 * a12;
    const double spread = camera.pixel_spread();

    Vec2* const derivatives[2] = {&hit.duv_dx, &hit.duv_dy};
    const DVec3 offsets[2] = {e1, e2};
    for (int i = 0; i < 2; ++i) {
        // The neighbouring ray, from the pinhole towards w + spread e, meets the plane at t.
        const DVec3 direction = w + spread * offsets[i];
        const double t = normal_distance / glm::dot(normal, direction);
        if (!(t > 0.0) || !std::isfinite(t) || !(determinant > 0.0)) {
            hit.duv_dx = hit.duv_dy = Vec2(1.0f);
            return;
        }
        const DVec3 dp = DVec3(camera.position()) + t * direction - DVec3(hit.position);
        const double e1_dp = glm::dot(edge1, dp), e2_dp = glm::dot(edge2, dp);
        const double d_b1 = (a22 * e1_dp - a12 * e2_dp) / determinant;
        const double d_b2 = (a11 * e2_dp - a12 * e1_dp) / determinant;
        // Without texture coordinates, uv is (b1, b2) (make_hit).
        Vec2 duv(static_cast<float>(d_b1), static_cast<float>(d_b2));
        if (!mesh.uvs.empty()) {
            const Vec2 uv0 = mesh.uvs[index[0]];
            duv = static_cast<float>(d_b1) * (mesh.uvs[index[1]] - uv0) + static_cast<float>(d_b2) * (mesh.uvs[index[2]] - uv0);
        }
        *derivatives[i] = duv;
    }
}
// END BOOK

}  // namespace freezeray::ch08
