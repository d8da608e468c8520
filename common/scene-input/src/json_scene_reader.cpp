// The JSON scene format (scenes/README.md): a JSON file naming OBJ/MTL meshes, read into a
// SceneDescription. Everything specific to the format is here: the JSON itself, the camera's
// keys, OBJ files with their MTL materials and the JSON overrides of those by name, transforms.
#include "freezeray/scene_readers.hpp"

#include "freezeray/error.hpp"
#include "freezeray/material_from_mtl.hpp"
#include "freezeray/obj_loader.hpp"
#include "freezeray/parameters.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace freezeray {

namespace {

// Largest image the renderer accepts (the film keeps 56 bytes a pixel).
constexpr long long MaximumPixels = 1LL << 26;  // 67 million pixels, 3.8 GB of film

nlohmann::json parse_json_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::error_code error;
        if (!std::filesystem::exists(path, error)) throw InputError(path, "scene file does not exist");
        throw InputError(path, "scene file cannot be read");
    }
    std::stringstream text_stream;
    text_stream << in.rdbuf();
    const std::string text = text_stream.str();
    // "path:line:column" of a byte offset, for messages.
    auto where = [&](std::size_t offset) {
        offset = std::min(offset, text.size());
        std::size_t line = 1, column = 1;
        for (std::size_t i = 0; i < offset; ++i) {
            if (text[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        return path + ":" + std::to_string(line) + ":" + std::to_string(column);
    };
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        std::string reason = e.what();
        const std::size_t colon = reason.find("syntax error");
        if (colon != std::string::npos) reason = reason.substr(colon);
        throw InputError(where(e.byte > 0 ? e.byte - 1 : 0), "malformed JSON: " + reason);
    } catch (const nlohmann::json::exception& e) {
        // A number too large for a double ("1e400") is an out_of_range error without a position
        // (found by fuzz_scene_json); its message quotes the number, so look for it in the text.
        const std::string reason = e.what();
        const std::size_t first = reason.find('\''), last = reason.rfind('\'');
        const std::string token = first < last ? reason.substr(first + 1, last - first - 1) : std::string();
        const std::size_t offset = token.empty() ? std::string::npos : text.find(token);
        throw InputError(offset == std::string::npos ? path : where(offset),
                         token.empty() ? "malformed JSON: " + reason
                                       : "malformed JSON: the number " + token + " is too large");
    }
}

bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What every camera states (the camera's own keys are its factory's to read).
CameraDescription read_camera(const Parameters& p) {
    CameraDescription camera;
    camera.position = p.require_vec3("position");
    camera.look_at = p.require_vec3("look_at");
    camera.up = p.get_vec3("up", Vec3(0, 1, 0));
    camera.fov_vertical_degrees = p.check_range("fov_vertical_degrees", p.require_float("fov_vertical_degrees"), 1e-3f, 179.0f);
    if (p.has("resolution")) {
        const nlohmann::json& r = p.json().at("resolution");
        if (!r.is_array() || r.size() != 2 || !r[0].is_number_integer() || !r[1].is_number_integer())
            throw InputError(p.where("resolution"), "expected [width, height] as two whole numbers");
        const long long w = r[0].get<long long>(), h = r[1].get<long long>();
        if (w < 1 || h < 1 || w > 65536 || h > 65536 || w * h > MaximumPixels)
            throw InputError(p.where("resolution"), "resolution " + std::to_string(w) + "x" + std::to_string(h) +
                                                        " is not between 1x1 and 65536x65536 with at most " +
                                                        std::to_string(MaximumPixels) + " pixels");
        camera.width = static_cast<int>(w);
        camera.height = static_cast<int>(h);
    }
    // The camera's frame must exist in single precision (Camera normalises these).
    const Vec3 forward = camera.look_at - camera.position;
    if (glm::length(forward) == 0.0f) throw InputError(p.where("look_at"), "equals the camera position");
    if (!is_finite(glm::normalize(forward)))
        throw InputError(p.where("look_at"), "is too far from the camera position for single precision");
    if (!is_finite(glm::normalize(camera.up))) throw InputError(p.where("up"), "must be a direction (not zero)");
    const Vec3 right = glm::cross(glm::normalize(forward), glm::normalize(camera.up));
    if (glm::length(right) == 0.0f || !is_finite(glm::normalize(right)))
        throw InputError(p.where("up"), "is parallel to the view direction");
    return camera;
}

// The object-to-world matrix of a mesh: either "matrix" (16 numbers, row-major) or
// translate * rotate * scale.
Mat4 read_transform(const Parameters& p, std::vector<std::string>& warnings) {
    if (p.has("matrix")) {
        for (const char* key : {"translate", "rotate", "scale"})
            if (p.json().contains(key))
                throw InputError(p.where(key), "cannot be combined with \"matrix\" (give one or the other)");
        const nlohmann::json& m = p.json().at("matrix");
        if (!m.is_array() || m.size() != 16) throw InputError(p.where("matrix"), "expected 16 numbers (row-major 4x4)");
        Mat4 result(1.0f);
        for (int row = 0; row < 4; ++row)
            for (int column = 0; column < 4; ++column) {
                const std::string where = p.where("matrix") + "/" + std::to_string(row * 4 + column);
                const nlohmann::json& e = m[static_cast<std::size_t>(row * 4 + column)];
                if (!e.is_number()) throw InputError(where, "expected a number");
                const double value = e.get<double>();
                if (!std::isfinite(value) || std::abs(value) > 3.0e38)
                    throw InputError(where, "the number is not finite in single precision");
                result[column][row] = static_cast<float>(value);  // GLM is column-major
            }
        for (std::string& w : p.unused_key_warnings()) warnings.push_back(std::move(w));
        return result;
    }
    Mat4 result(1.0f);
    result = glm::translate(result, p.get_vec3("translate", Vec3(0.0f)));
    if (p.has("rotate")) {
        const Parameters r = p.child("rotate");
        const Vec3 axis = r.require_vec3("axis");
        if (!is_finite(glm::normalize(axis))) throw InputError(r.where("axis"), "must be a direction (not zero)");
        result = glm::rotate(result, glm::radians(r.require_float("degrees")), glm::normalize(axis));
        for (std::string& w : r.unused_key_warnings()) warnings.push_back(std::move(w));
    }
    const Vec3 scale = p.has("scale") && p.json().at("scale").is_number() ? Vec3(p.get_float("scale", 1.0f))
                                                                          : p.get_vec3("scale", Vec3(1.0f));
    if (scale.x * scale.y * scale.z == 0.0f) throw InputError(p.where("scale"), "must not be zero");
    for (std::string& w : p.unused_key_warnings()) warnings.push_back(std::move(w));
    return glm::scale(result, scale);
}

// The MTL maps the renderer reads nothing from, said once per kind and file rather than dropped in
// silence: bump or normal maps (map_bump / bump: shading uses the mesh's own normals). (Alpha
// masks, map_d, become the materials' "alpha"; a chapter without image textures says so as an
// unused key.)
std::vector<std::string> unused_maps_warnings(const std::vector<MtlMaterial>& materials) {
    std::vector<std::string> warnings;
    const auto warn = [&](std::string MtlMaterial::*map, const std::string& what) {
        std::string names, file;
        std::size_t count = 0;
        for (const MtlMaterial& m : materials) {
            if ((m.*map).empty()) continue;
            if (count < 4) names += (count > 0 ? ", " : "") + m.name;
            if (file.empty()) file = m.where.substr(0, m.where.rfind(':'));
            ++count;
        }
        if (count == 0) return;
        if (count > 4) names += ", ...";
        warnings.push_back(file + ": " + std::to_string(count) + " material" + (count == 1 ? "" : "s") + " (" + names +
                           ") name " + what);
    };
    warn(&MtlMaterial::map_bump,
         "a bump or normal map (map_bump, bump), which this renderer does not read: shading uses the mesh's normals");
    return warnings;
}

// A block of the top level ("render", "textures", "accelerator") as the builder reads it.
ParameterBlock top_block(const Parameters& top, const nlohmann::json& root, const std::string& key) {
    ParameterBlock block;
    block.file = top.file();
    block.path = "/" + key;
    if (top.has(key)) {
        block.json = root.at(key);  // the builder's Parameters refuses anything but an object, naming the path
        block.given = true;
    }
    return block;
}

}  // namespace

SceneDescription read_json_scene(const std::string& path) {
    SceneDescription scene;
    scene.file = path;
    const nlohmann::json root = parse_json_file(path);
    const std::string base = std::filesystem::path(path).parent_path().string();
    scene.base_directory = base;
    const Parameters top(root, path, "", base);
    top.get_string("description", "");
    top.get_int("chapter", 1);

    // The camera: what every camera states is read here; the block's other keys ("type" and the
    // type's own) are the camera factory's.
    const Parameters camera_block = top.child("camera");
    scene.camera = read_camera(camera_block);
    scene.camera_block = {camera_block.json(), path, "/camera", true,
                          {"position", "look_at", "up", "fov_vertical_degrees", "resolution"}};

    scene.render = top_block(top, root, "render");
    scene.textures = top_block(top, root, "textures");
    scene.accelerator = top_block(top, root, "accelerator");

    // Material overrides by name: {"name": {...}}; with a "type" they replace the MTL
    // material, without one they change some of its parameters.
    const nlohmann::json no_overrides = nlohmann::json::object();
    const nlohmann::json& overrides = top.has("materials") ? root.at("materials") : no_overrides;
    if (!overrides.is_object()) throw InputError(top.where("materials"), "expected an object of materials by name");
    std::map<std::string, std::uint32_t> material_index;  // by name, across all meshes
    std::set<std::string> overrides_used;

    auto add_material = [&](const std::string& name, nlohmann::json description, std::string file, std::string json_path) {
        const auto override_it = overrides.find(name);
        if (override_it != overrides.end()) {
            if (!override_it->is_object()) throw InputError(top.where("materials") + "/" + name, "expected an object");
            if (override_it->contains("type")) description = nlohmann::json::object();
            description.update(*override_it);
            file = path;
            json_path = "/materials/" + name;
            overrides_used.insert(name);
        }
        scene.materials.push_back({name, {std::move(description), std::move(file), std::move(json_path), true, {}}});
        material_index[name] = static_cast<std::uint32_t>(scene.materials.size() - 1);
        return material_index[name];
    };

    if (!top.has("meshes")) throw InputError(top.where("meshes"), "is required (an array of meshes)");
    const nlohmann::json& meshes = root.at("meshes");
    if (!meshes.is_array() || meshes.empty()) throw InputError(top.where("meshes"), "expected a non-empty array");
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const Parameters m(meshes[i], path, "/meshes/" + std::to_string(i), base);
        const std::string obj_path = m.require_existing_file("file");
        const Mat4 transform = m.has("transform") ? read_transform(m.child("transform"), scene.warnings) : Mat4(1.0f);
        const std::string forced_material = m.get_string("material", "");
        for (std::string& w : m.unused_key_warnings()) scene.warnings.push_back(std::move(w));

        ObjLoadResult obj = load_obj(obj_path);
        // (load_obj's warnings already say how many degenerate triangles it dropped.)
        for (std::string& w : obj.warnings) scene.warnings.push_back(std::move(w));

        // Map this file's MTL materials onto scene materials (shared by name across files).
        std::vector<std::uint32_t> local_to_scene(obj.materials.size());
        if (!forced_material.empty()) {
            if (!overrides.contains(forced_material))
                throw InputError(m.where("material"), "names material '" + forced_material + "', which /materials does not define");
            const auto it = material_index.find(forced_material);
            const std::uint32_t index = it != material_index.end()
                                            ? it->second
                                            : add_material(forced_material, nlohmann::json::object(), path, "");
            std::fill(local_to_scene.begin(), local_to_scene.end(), index);
        } else {
            for (std::size_t k = 0; k < obj.materials.size(); ++k) {
                const MtlMaterial& mtl = obj.materials[k];
                const auto it = material_index.find(mtl.name);
                local_to_scene[k] = it != material_index.end() ? it->second
                                                               : add_material(mtl.name, material_from_mtl(mtl), mtl.where, "");
            }
            for (std::string& w : unused_maps_warnings(obj.materials)) scene.warnings.push_back(std::move(w));
        }
        for (TriangleMesh& mesh : obj.meshes) {
            for (std::uint32_t& f : mesh.face_materials) f = local_to_scene[f];
            try {
                mesh.transform(transform);
            } catch (const InputError& e) {
                throw InputError(m.where("transform"), e.what());
            }
            for (const Vec3& p : mesh.positions)
                if (!is_finite(p))
                    throw InputError(m.where("transform"), "moves mesh '" + mesh.name +
                                                               "' beyond the range of single precision");
            scene.meshes.push_back(std::move(mesh));
        }
    }
    for (const auto& [name, value] : overrides.items())
        if (!overrides_used.count(name))
            scene.warnings.push_back(top.where("materials") + "/" + name + ": material '" + name +
                                     "' is not used by any mesh");

    // The "lights" array: each light's parameters, for the builder.
    if (top.has("lights")) {
        const nlohmann::json& lights = root.at("lights");
        if (!lights.is_array()) throw InputError(top.where("lights"), "expected an array of lights");
        for (std::size_t i = 0; i < lights.size(); ++i)
            scene.lights.push_back({lights[i], path, "/lights/" + std::to_string(i), true, {}});
    }
    for (std::string& w : top.unused_key_warnings()) scene.warnings.push_back(std::move(w));
    return scene;
}

}  // namespace freezeray
