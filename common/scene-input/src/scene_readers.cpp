// Choosing the reader of a scene file by its extension.
#include "freezeray/scene_readers.hpp"

#include "freezeray/error.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace freezeray {

const std::vector<SceneReader>& scene_readers() {
    static const std::vector<SceneReader> readers = {
        {".json", "FreezeRay's JSON scene with OBJ/MTL meshes (scenes/README.md)", read_json_scene},
    };
    return readers;
}

SceneDescription read_scene_description(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw InputError(path, "scene file does not exist");
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::string formats;
    for (const SceneReader& reader : scene_readers()) {
        if (extension == reader.extension) return reader.read(path);
        formats += (formats.empty() ? "" : "; ") + std::string(reader.extension) + ": " + reader.format;
    }
    throw InputError(path, "is not a scene file this renderer reads (by its extension: " + formats + ")");
}

}  // namespace freezeray
