// Loading a Wavefront OBJ file into triangle meshes, in three steps:
//   1. check the text ourselves (obj_text_check.cpp), because tinyobjloader accepts malformed
//      numbers and out-of-range indices without a word, and read the MTL files (mtl_loader.cpp);
//   2. let tinyobjloader parse the OBJ into shapes of polygons;
//   3. turn each shape into a TriangleMesh: fan triangles, one vertex per distinct
//      (position, texture coordinate, normal) index triple, degenerate triangles dropped.
#include "freezeray/obj_loader.hpp"

#include "freezeray/error.hpp"
#include "mtl_loader.hpp"
#include "freezeray/obj_text_check.hpp"

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>
#include <unordered_map>

namespace freezeray {
namespace {

namespace fs = std::filesystem;

// Hands tinyobjloader all the materials read beforehand, on its first call. tinyobjloader
// resolves a `usemtl` name only against the MTL files it has read so far, and reads only the
// first existing file of an `mtllib a.mtl b.mtl` line; this way every material of every MTL
// file is known before the first `usemtl`. The OBJ text given to tinyobjloader starts with one
// extra `mtllib` line so that this call comes first.
class PreloadedMaterials : public tinyobj::MaterialReader {
public:
    explicit PreloadedMaterials(const obj_detail::MtlLibrary& library) : library_(library) {}

    bool operator()(const std::string& /*file_name*/, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* index_by_name, std::string* /*warning*/,
                    std::string* /*error*/) override {
        if (materials->empty()) {
            *materials = library_.parsed;
            *index_by_name = library_.index_by_name;
        }
        return true;
    }

private:
    const obj_detail::MtlLibrary& library_;
};

const std::string first_line_for_tinyobjloader = "mtllib (all materials)\n";

// Reads every MTL file the OBJ names, relative to the OBJ's folder, each once. Then checks that
// every `usemtl` names a material one of them defines.
obj_detail::MtlLibrary load_materials(const obj_detail::ObjTextSummary& summary, const std::string& obj_path) {
    obj_detail::MtlLibrary library;
    std::set<std::string> loaded;
    const fs::path folder = fs::path(obj_path).parent_path();
    for (const obj_detail::MtllibStatement& mtllib : summary.mtllibs) {
        for (const std::string& file_name : mtllib.file_names) {
            const std::string mtl_path = (folder / file_name).lexically_normal().string();
            if (!loaded.insert(mtl_path).second) continue;
            std::error_code error;
            if (!fs::is_regular_file(mtl_path, error))
                throw InputError(obj_path + ":" + std::to_string(mtllib.line),
                                 "MTL file '" + file_name + "' does not exist (looked for " +
                                     fs::absolute(mtl_path).string() + ")");
            obj_detail::load_mtl_file(mtl_path, library);
        }
    }
    for (const obj_detail::UsemtlStatement& usemtl : summary.usemtls) {
        if (!library.index_by_name.contains(usemtl.material_name))
            throw InputError(obj_path + ":" + std::to_string(usemtl.line),
                             "usemtl '" + usemtl.material_name + "' names a material that no MTL file defines" +
                                 (summary.mtllibs.empty() ? " (the file has no mtllib line)" : ""));
    }
    return library;
}

// One distinct OBJ vertex: its (position, texture coordinate, normal) index triple, -1 when absent.
struct VertexKey {
    int position, uv, normal;
    bool operator==(const VertexKey&) const = default;
};

// Spreads index triples over the hash table: the three indices are combined with large odd
// multipliers, then mixed by the splitmix64 finaliser (Steele et al., "Fast splittable
// pseudorandom number generators", OOPSLA 2014), so that neighbouring triples do not collide.
struct VertexKeyHash {
    std::size_t operator()(const VertexKey& key) const {
        std::uint64_t h = static_cast<std::uint32_t>(key.position) * 0x9E3779B97F4A7C15ull +
                          static_cast<std::uint32_t>(key.uv) * 0xC2B2AE3D27D4EB4Full +
                          static_cast<std::uint32_t>(key.normal) * 0x165667B19E3779F9ull;
        h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
        h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
        return static_cast<std::size_t>(h ^ (h >> 31));
    }
};

bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// True when a triangle has a non-finite coordinate or no area in float arithmetic: the cross
// product of two edges, computed in float as the renderer computes it, is exactly zero (a
// repeated vertex, two equal positions, points on one line). Such a triangle has no normal.
// A triangle that is merely tiny keeps a non-zero cross product and is kept.
bool is_degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
    if (!is_finite(a) || !is_finite(b) || !is_finite(c)) return true;
    const Vec3 n = glm::cross(b - a, c - a);
    return n.x == 0.0f && n.y == 0.0f && n.z == 0.0f;
}

// The unit normal of a non-degenerate triangle, on the side from which a-b-c turns
// counter-clockwise. The cross product is first divided by its largest component so that a
// tiny triangle's squared length does not underflow to zero.
Vec3 unit_geometric_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = glm::cross(b - a, c - a);
    return glm::normalize(n / max_component(glm::abs(n)));
}

// Builds the TriangleMesh of one tinyobjloader shape.
class MeshBuilder {
public:
    MeshBuilder(const tinyobj::attrib_t& attrib, const tinyobj::shape_t& shape) : attrib_(attrib) {
        for (const tinyobj::index_t& corner : shape.mesh.indices) {
            has_normals_ = has_normals_ || corner.normal_index >= 0;
            has_uvs_ = has_uvs_ || corner.texcoord_index >= 0;
        }
        vertex_of_.reserve(shape.mesh.indices.size());
    }

    // Adds triangle a-b-c (winding kept) unless it is degenerate; returns whether it was added.
    bool add_triangle(const tinyobj::index_t& a, const tinyobj::index_t& b, const tinyobj::index_t& c,
                      std::uint32_t material) {
        const Vec3 pa = position(a), pb = position(b), pc = position(c);
        if (is_degenerate(pa, pb, pc)) return false;
        const Vec3 normal = unit_geometric_normal(pa, pb, pc);
        mesh_.triangles.push_back({vertex(a, normal), vertex(b, normal), vertex(c, normal)});
        mesh_.face_materials.push_back(material);
        return true;
    }

    TriangleMesh take_mesh(std::string name) {
        mesh_.name = std::move(name);
        return std::move(mesh_);
    }

private:
    Vec3 position(const tinyobj::index_t& corner) const {
        const std::size_t i = 3 * static_cast<std::size_t>(corner.vertex_index);
        return Vec3(attrib_.vertices[i], attrib_.vertices[i + 1], attrib_.vertices[i + 2]);
    }

    // The mesh vertex of one face corner, shared by every corner with the same index triple.
    // When the shape has normals but this corner names none, it gets the triangle's geometric
    // normal; such a vertex belongs to its triangle alone and is not shared.
    std::uint32_t vertex(const tinyobj::index_t& corner, const Vec3& geometric_normal) {
        if (has_normals_ && corner.normal_index < 0) return append_vertex(corner, geometric_normal);
        const VertexKey key{corner.vertex_index, corner.texcoord_index, corner.normal_index};
        const auto [found, inserted] = vertex_of_.try_emplace(key, 0u);
        if (inserted) found->second = append_vertex(corner, geometric_normal);
        return found->second;
    }

    // Appends the vertex of one corner. A texture coordinate a corner does not name is (0, 0);
    // a written normal that cannot be normalised (zero, non-finite) becomes the geometric one.
    std::uint32_t append_vertex(const tinyobj::index_t& corner, const Vec3& geometric_normal) {
        mesh_.positions.push_back(position(corner));
        if (has_uvs_) {
            const std::size_t i = 2 * static_cast<std::size_t>(corner.texcoord_index);
            mesh_.uvs.push_back(corner.texcoord_index < 0 ? Vec2(0.0f)
                                                          : Vec2(attrib_.texcoords[i], attrib_.texcoords[i + 1]));
        }
        if (has_normals_) {
            Vec3 normal = geometric_normal;
            if (corner.normal_index >= 0) {
                const std::size_t i = 3 * static_cast<std::size_t>(corner.normal_index);
                const Vec3 written(attrib_.normals[i], attrib_.normals[i + 1], attrib_.normals[i + 2]);
                const float length = glm::length(written);
                if (length > 0.0f && std::isfinite(length)) normal = written / length;
            }
            mesh_.normals.push_back(normal);
        }
        return static_cast<std::uint32_t>(mesh_.positions.size() - 1);
    }

    const tinyobj::attrib_t& attrib_;
    bool has_normals_ = false;
    bool has_uvs_ = false;
    std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> vertex_of_;
    TriangleMesh mesh_;
};

// The name a mesh is known by: its OBJ object or group name, or the file's name for faces
// written before any `o` or `g` line.
std::string mesh_name(const std::string& shape_name, const std::string& obj_path) {
    const std::size_t first = shape_name.find_first_not_of(" \t");
    if (first == std::string::npos) return fs::path(obj_path).stem().string();
    return shape_name.substr(first, shape_name.find_last_not_of(" \t") - first + 1);
}

// Appends one mesh per shape that keeps at least one triangle, and counts the dropped ones.
// Faces without a material get `default_material`; returns whether any kept triangle has it.
bool add_meshes(const std::vector<tinyobj::shape_t>& shapes, const tinyobj::attrib_t& attrib,
                std::uint32_t default_material, const std::string& obj_path, ObjLoadResult& result) {
    bool default_material_used = false;
    for (const tinyobj::shape_t& shape : shapes) {
        MeshBuilder builder(attrib, shape);
        std::size_t first_corner = 0;
        for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
            const std::size_t corner_count = shape.mesh.num_face_vertices[face];
            const int material_id = shape.mesh.material_ids[face];
            const std::uint32_t material = material_id < 0 ? default_material : static_cast<std::uint32_t>(material_id);
            // Fan triangulation around the face's first corner: (0, k, k + 1).
            const tinyobj::index_t* corners = &shape.mesh.indices[first_corner];
            for (std::size_t k = 1; k + 1 < corner_count; ++k) {
                if (builder.add_triangle(corners[0], corners[k], corners[k + 1], material))
                    default_material_used = default_material_used || material_id < 0;
                else
                    ++result.dropped_degenerate_triangles;
            }
            first_corner += corner_count;
        }
        TriangleMesh mesh = builder.take_mesh(mesh_name(shape.name, obj_path));
        if (mesh.triangle_count() > 0) result.meshes.push_back(std::move(mesh));
    }
    return default_material_used;
}

}  // namespace

ObjLoadResult load_obj(const std::string& path) {
    std::error_code filesystem_error;
    if (!fs::is_regular_file(path, filesystem_error)) throw InputError(path, "the OBJ file does not exist");
    std::string text = first_line_for_tinyobjloader;
    if (!obj_detail::read_text_file(path, text)) throw InputError(path, "the OBJ file cannot be read");

    const obj_detail::ObjTextSummary summary =
        obj_detail::check_obj_text(std::string_view(text).substr(first_line_for_tinyobjloader.size()), path);
    if (summary.face_count == 0) throw InputError(path, "the OBJ file has no faces");
    obj_detail::MtlLibrary library = load_materials(summary, path);

    // Polygons stay whole (triangulate = false): tinyobjloader would cut quads along their
    // shorter diagonal and larger polygons by ear clipping, and we want plain fans.
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    PreloadedMaterials material_reader(library);
    std::istringstream stream(std::move(text));
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, &material_reader,
                          /*triangulate=*/false, /*default_vcols_fallback=*/false))
        throw InputError(path, "tinyobjloader cannot read the file: " + error);

    // tinyobjloader reads the words nan and inf as 0. Make such a vertex non-finite again (its x
    // is enough) so that the triangles using it are recognised as degenerate.
    for (const std::size_t i : summary.non_finite_positions)
        attrib.vertices[3 * i] = std::numeric_limits<float>::quiet_NaN();

    ObjLoadResult result;
    const auto default_material = static_cast<std::uint32_t>(library.materials.size());
    const bool default_material_used = add_meshes(shapes, attrib, default_material, path, result);
    if (result.meshes.empty())
        throw InputError(path, "the OBJ file has no faces with an area (" +
                                   std::to_string(result.dropped_degenerate_triangles) +
                                   " degenerate triangles dropped)");

    result.materials = std::move(library.materials);
    if (default_material_used) {
        MtlMaterial grey;
        grey.name = "default";
        grey.where = path;
        grey.kd = Spectrum(0.5f);
        result.materials.push_back(grey);
    }
    result.warnings = std::move(library.warnings);
    if (result.dropped_degenerate_triangles > 0)
        result.warnings.push_back(path + ": dropped " + std::to_string(result.dropped_degenerate_triangles) +
                                  " degenerate triangles (zero area, a repeated vertex or a non-finite coordinate)");
    return result;
}

}  // namespace freezeray
