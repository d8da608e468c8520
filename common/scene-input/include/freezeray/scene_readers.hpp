// The scene file formats the renderer reads, each a reader from a file to a SceneDescription,
// chosen by the file's extension. Another format is one more reader and one more line of
// scene_readers().
#pragma once

#include "freezeray/scene_description.hpp"

#include <string>
#include <vector>

namespace freezeray {

// The JSON scene format with OBJ/MTL meshes (scenes/README.md). Throws InputError naming the file
// and JSON path, or file:line, of anything wrong.
SceneDescription read_json_scene(const std::string& path);

struct SceneReader {
    const char* extension;  // ".json"
    const char* format;     // "FreezeRay JSON scene (scenes/README.md)"
    SceneDescription (*read)(const std::string& path);
};
// Every reader, in the order `info` and messages list them.
const std::vector<SceneReader>& scene_readers();

// Reads `path` with the reader of its extension; an extension no reader takes is an InputError
// that lists the formats.
SceneDescription read_scene_description(const std::string& path);

}  // namespace freezeray
