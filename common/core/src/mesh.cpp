// Triangle meshes: bounds, areas and placing a mesh in the world.
#include "freezeray/mesh.hpp"

#include "freezeray/error.hpp"

#include <cmath>
#include <utility>

namespace freezeray {

Bounds3 TriangleMesh::bounds() const {
    Bounds3 box;
    for (const Vec3& p : positions) box.expand(p);
    return box;
}

// Half the length of the edges' cross product. The length is taken in double: for a very small
// triangle the squared length of the float cross product would underflow to zero.
float TriangleMesh::triangle_area(std::size_t triangle) const {
    const auto& [a, b, c] = triangles[triangle];
    const Vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
    const double x = n.x, y = n.y, z = n.z;
    return static_cast<float>(0.5 * std::sqrt(x * x + y * y + z * z));
}

// Positions are transformed as points (the matrix is taken as affine: its last row is not
// used), normals by the inverse transpose of its 3x3 part, which keeps them perpendicular to
// the transformed surface, then renormalised.
//
// The front side of a triangle is the side from which its vertices turn counter-clockwise. A
// mirroring matrix (negative determinant) reverses that turning, so the front side would stop
// agreeing with the transformed normals: swapping two vertices of every triangle restores it.
// Throws InputError for a matrix that flattens the mesh (determinant 0 or not finite).
void TriangleMesh::transform(const Mat4& object_to_world) {
    const glm::mat3 linear(object_to_world);
    const float determinant = glm::determinant(linear);
    if (determinant == 0.0f || !std::isfinite(determinant))
        throw InputError("mesh '" + name + "'", "its transform cannot be inverted (determinant " +
                                                    std::to_string(determinant) + "): it would flatten the mesh");

    for (Vec3& p : positions) p = Vec3(object_to_world * glm::vec4(p, 1.0f));
    if (!normals.empty()) {
        const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
        for (Vec3& n : normals) n = glm::normalize(normal_matrix * n);
    }
    if (determinant < 0.0f) {
        for (auto& triangle : triangles) std::swap(triangle[1], triangle[2]);
    }
}

}  // namespace freezeray
