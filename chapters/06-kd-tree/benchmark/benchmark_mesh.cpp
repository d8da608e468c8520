// Loading an OBJ file in tinyobjloader's triangulate = true order (see benchmark_mesh.hpp).
#include "benchmark_mesh.hpp"

#include "freezeray/error.hpp"
#include "freezeray/obj_text_check.hpp"

#include <tiny_obj_loader.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <sstream>

namespace freezeray::benchmark {

TriangleMesh load_benchmark_mesh(const std::string& path) {
    std::error_code filesystem_error;
    if (!std::filesystem::is_regular_file(path, filesystem_error)) throw InputError(path, "the OBJ file does not exist");
    std::string text;
    if (!obj_detail::read_text_file(path, text)) throw InputError(path, "the OBJ file cannot be read");

    // tinyobjloader turns malformed numbers into 0 and keeps face indices past the end of the
    // vertex list (then reads out of bounds); the renderer's first pass refuses both with a line
    // number, so the benchmark uses it too.
    const obj_detail::ObjTextSummary summary = obj_detail::check_obj_text(text, path);
    if (summary.face_count == 0) throw InputError(path, "the OBJ file has no faces");
    // tinyobjloader reads the words nan and inf as 0: another tool reading the file with it
    // would trace a different triangle than we would, so such a file is refused.
    if (!summary.non_finite_positions.empty())
        throw InputError(path, "vertex " + std::to_string(summary.non_finite_positions.front() + 1) +
                                   " (the 'v' lines counted from 1) is written with nan or inf; the benchmark needs "
                                   "finite vertices");

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    std::istringstream stream(std::move(text));
    // No material reader: mtllib lines are skipped, and materials do not change the faces or
    // their order.
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, /*readMatFn=*/nullptr,
                          /*triangulate=*/true, /*default_vcols_fallback=*/false))
        throw InputError(path, "tinyobjloader cannot read the file: " + error);

    TriangleMesh mesh;
    mesh.name = std::filesystem::path(path).stem().string();
    mesh.positions.reserve(attrib.vertices.size() / 3);
    for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
        mesh.positions.emplace_back(attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]);

    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t corner = 0;
        for (const unsigned int corner_count : shape.mesh.num_face_vertices) {
            // Triangulation gives triangles only; anything else would be a tinyobjloader we do
            // not know, whose numbering we cannot promise.
            if (corner_count != 3)
                throw InputError(path, "tinyobjloader left a face with " + std::to_string(corner_count) +
                                           " corners after triangulation (shape '" + shape.name + "')");
            std::array<std::uint32_t, 3> triangle{};
            for (int k = 0; k < 3; ++k) {
                const int index = shape.mesh.indices[corner + k].vertex_index;
                if (index < 0 || static_cast<std::size_t>(index) >= mesh.positions.size())
                    throw InputError(path, "tinyobjloader gave vertex index " + std::to_string(index) + " of " +
                                               std::to_string(mesh.positions.size()) + " vertices");
                triangle[k] = static_cast<std::uint32_t>(index);
            }
            mesh.triangles.push_back(triangle);
            corner += 3;
        }
    }
    if (mesh.triangles.empty()) throw InputError(path, "tinyobjloader found no faces with three or more corners");
    if (mesh.triangles.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw InputError(path, "more triangles than FRHITS01's int32 indices can name");
    mesh.face_materials.assign(mesh.triangles.size(), 0u);
    return mesh;
}

}  // namespace freezeray::benchmark
