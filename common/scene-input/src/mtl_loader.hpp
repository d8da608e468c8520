// Reading the MTL files an OBJ file names. tinyobjloader parses the values; this adds what it
// does not keep: the line of each `newmtl` (for messages), which statements a block actually
// wrote (tinyobjloader sets Pr and Pm to 0 whether they are written or not), and texture paths
// resolved to files that exist. Private to obj_loader.cpp.
#pragma once

#include "freezeray/obj_loader.hpp"

#include <tiny_obj_loader.h>

#include <map>
#include <string>
#include <vector>

namespace freezeray::obj_detail {

// The materials of all the MTL files of one OBJ file, in order of definition.
struct MtlLibrary {
    std::vector<MtlMaterial> materials;
    // The same materials as tinyobjloader parsed them (same indices), handed to its OBJ reader
    // so that `usemtl` selects them.
    std::vector<tinyobj::material_t> parsed;
    // Material index by name. The first definition of a name wins, as in tinyobjloader.
    std::map<std::string, int> index_by_name;
    std::vector<std::string> warnings;
};

// Reads one MTL file and appends its materials to `library`. `path` is how messages name it;
// texture maps are resolved relative to its folder. Throws InputError for an unreadable file,
// a malformed value or a texture map that does not exist, with "file.mtl:LINE" where it can.
void load_mtl_file(const std::string& path, MtlLibrary& library);

}  // namespace freezeray::obj_detail
