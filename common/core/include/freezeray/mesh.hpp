// Triangle meshes as the renderer stores them: shared vertex arrays and index triples.
#pragma once

#include "freezeray/math.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace freezeray {

struct TriangleMesh {
    std::string name;                          // object or group name, for messages
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;                 // per-vertex shading normals; empty when absent
    std::vector<Vec2> uvs;                     // per-vertex texture coordinates; empty when absent
    std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into the vertex arrays
    std::vector<std::uint32_t> face_materials; // per triangle: index into the scene's materials

    std::size_t triangle_count() const { return triangles.size(); }
    Bounds3 bounds() const;
    float triangle_area(std::size_t triangle) const;

    // Applies an affine transform to positions and (inverse-transpose) to normals.
    void transform(const Mat4& object_to_world);
};

}  // namespace freezeray
