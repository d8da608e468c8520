// Wavefront OBJ/MTL loading (through tinyobjloader) into triangle meshes and material records.
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/mesh.hpp"

#include <optional>
#include <string>
#include <vector>

namespace freezeray {

// One `newmtl` block of an MTL file, as written. Which renderer material it becomes is decided
// later (scene_loader.cpp, material_from_mtl) so that JSON overrides can replace it.
struct MtlMaterial {
    std::string name;
    std::string where;           // "file.mtl:LINE" of its newmtl line, for messages
    Spectrum kd{0.0f};           // diffuse reflectance
    Spectrum ks{0.0f};           // specular reflectance
    Spectrum ke{0.0f};           // emitted radiance
    Spectrum tf{1.0f};           // transmission filter
    float ns = 0.0f;             // Phong exponent
    float ni = 1.5f;             // index of refraction (1.5, the usual glass, when Ni is not written)
    float dissolve = 1.0f;       // d
    int illum = 2;               // illumination model
    std::optional<float> pr;     // PBR extension: roughness
    std::optional<float> pm;     // PBR extension: metallic
    // Texture maps, as absolute (resolved) paths; empty when absent. The loader has checked
    // that every named file exists.
    std::string map_kd, map_ks, map_ns, map_pr, map_pm, map_bump, map_d;
};

struct ObjLoadResult {
    // One mesh per OBJ object/group; face_materials index into `materials` below.
    std::vector<TriangleMesh> meshes;
    std::vector<MtlMaterial> materials;
    // Triangles dropped because they were degenerate (zero area, repeated vertex, non-finite
    // coordinate). The caller reports the count as a warning.
    std::size_t dropped_degenerate_triangles = 0;
    std::vector<std::string> warnings;
};

// Loads an OBJ file and the MTL files it names (relative to the OBJ's folder). Polygons are
// fan-triangulated. Faces without a material get the index of an added default material named
// "default" (diffuse grey 0.5). Throws InputError with "file:line" for a missing file, a
// malformed line, an index out of range, a missing MTL or texture file.
ObjLoadResult load_obj(const std::string& path);

}  // namespace freezeray
