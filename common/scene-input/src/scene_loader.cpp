// Loading a JSON scene: camera, meshes with transforms, materials (from MTL, overridden by
// name in JSON), render defaults. The format is documented in scenes/README.md.
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include "freezeray/error.hpp"
#include "freezeray/material_from_mtl.hpp"
#include "freezeray/obj_loader.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/registry.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <filesystem>
#include <algorithm>
#include <map>
#include <set>
#include <fstream>
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

// Builds one material from its JSON description through the registry.
std::unique_ptr<Material> build_material(const std::string& name, const nlohmann::json& description,
                                         const std::string& file, const std::string& path,
                                         const std::string& base_directory, const MaterialContext& context,
                                         std::vector<std::string>& warnings) {
    const Parameters p(description, file, path, base_directory);
    const std::string type = p.require_string("type");
    const Spectrum emission = p.get_spectrum("emission", Spectrum(0.0f));
    for (int c = 0; c < 3; ++c) p.check_range("emission", emission[c], 0.0f, 1e30f);
    std::unique_ptr<Material> material = context.registry.materials.make(type, p.where("type"), p, context);
    material->name = name;
    material->type = type;
    material->emission = emission;
    // An area light samples points all over its triangles; holes in it would be lit points that
    // are not there.
    if (material->alpha_mask && material->is_emissive())
        throw InputError(p.where("emission"), "an emissive material cannot have an alpha mask (\"alpha\")");
    for (std::string& w : p.unused_key_warnings()) warnings.push_back(std::move(w));
    return material;
}

// The scene's "lights" array: analytic lights and the environment, made by the registry (chapter
// 03 registers them). At most one light may be at infinity.
void read_lights(const Parameters& top, const nlohmann::json& root, Scene& scene, const Registry& registry) {
    if (!top.has("lights")) return;
    const nlohmann::json& lights = root.at("lights");
    if (!lights.is_array()) throw InputError(top.where("lights"), "expected an array of lights");
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Parameters p(lights[i], top.file(), "/lights/" + std::to_string(i), top.base_directory());
        const std::string type = p.require_string("type");
        if (type == "area")
            throw InputError(p.where("type"), "area lights come from emissive materials (\"emission\" or MTL Ke), "
                                              "not from the \"lights\" array");
        std::unique_ptr<Light> light = registry.lights.make(type, p.where("type"), p);
        light->where = p.where();
        for (std::string& w : p.unused_key_warnings()) scene.warnings.push_back(std::move(w));
        if (light->type() == LightType::Infinite) {
            if (scene.environment != nullptr)
                throw InputError(p.where("type"), "a scene has at most one environment (" + scene.environment->where +
                                                      " is the first)");
            scene.environment = light.get();
        }
        scene.lights.push_back(std::move(light));
    }
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

}  // namespace

Scene load_scene(const std::string& path, const Registry& registry, const SceneLoadOptions& options) {
    Scene scene;
    scene.file = path;
    const nlohmann::json root = parse_json_file(path);
    const std::string base = std::filesystem::path(path).parent_path().string();
    const Parameters top(root, path, "", base);
    top.get_string("description", "");
    top.get_int("chapter", 1);

    // The camera: the registered kind the block's "type" names, else the default (the pinhole).
    const Parameters camera_block = top.child("camera");
    scene.camera_description = read_camera(camera_block);
    if (options.width > 0) scene.camera_description.width = options.width;
    if (options.height > 0) scene.camera_description.height = options.height;
    scene.camera_type = camera_block.get_string("type", registry.cameras.default_name());
    scene.camera = registry.cameras.make(scene.camera_type, camera_block.has("type") ? camera_block.where("type") : "camera",
                                         scene.camera_description, camera_block);
    for (std::string& w : camera_block.unused_key_warnings()) scene.warnings.push_back(std::move(w));

    // The layout image textures are stored in: the command line's, else the "textures" block's,
    // else the renderer's default (none before chapter 02, which has no image textures).
    // Its settings are read (and checked) here, whether or not the scene has image textures.
    scene.texture_layout = registry.texture_layouts.default_name();
    const OptionParameters textures(top.has("textures") ? &root.at("textures") : nullptr, path, "/textures", base,
                                    options.options, registry.options(), OptionTarget::Textures);
    const Parameters& texture_settings = textures.parameters();
    scene.texture_layout = texture_settings.get_string("layout", scene.texture_layout);
    if (texture_settings.has("layout"))
        registry.require(CapabilityKind::TextureLayout, scene.texture_layout, texture_settings.where("layout"));
    if (!scene.texture_layout.empty())
        registry.texture_storage_maker(scene.texture_layout, texture_settings.where("layout"), &texture_settings);
    for (std::string& w : texture_settings.unused_key_warnings()) scene.warnings.push_back(std::move(w));
    const MaterialContext material_context{registry, scene.texture_layout, &texture_settings, &scene.textures};

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
        scene.materials.push_back(build_material(name, description, file, json_path, base, material_context, scene.warnings));
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

    if (top.has("render")) {
        const Parameters r = top.child("render");
        scene.defaults.integrator = r.get_string("integrator", "");
        const int spp = r.get_int("spp", 16);
        if (spp < 1) throw InputError(r.where("spp"), "must be at least 1");
        scene.defaults.samples_per_pixel = static_cast<std::uint64_t>(spp);
        scene.defaults.max_depth = r.get_int("max_depth", 0);
        if (scene.defaults.max_depth < 0) throw InputError(r.where("max_depth"), "must not be negative");
        scene.defaults.seed = static_cast<std::uint64_t>(r.get_int("seed", 0));
        scene.defaults.sampler = r.get_string("sampler", "");
        if (!scene.defaults.sampler.empty()) registry.require(CapabilityKind::Sampler, scene.defaults.sampler, r.where("sampler"));
        scene.defaults.light_sampler = r.get_string("light_sampler", "");
        if (!scene.defaults.light_sampler.empty())
            registry.require(CapabilityKind::LightSampler, scene.defaults.light_sampler, r.where("light_sampler"));
        // The keys of the integrators' options go to the integrator's factory, which checks them.
        for (const OptionDeclaration& d : registry.options())
            if (d.target == OptionTarget::Integrator && r.has(d.key))
                scene.defaults.integrator_options[d.key] = r.json().at(d.key);
        for (std::string& w : r.unused_key_warnings()) scene.warnings.push_back(std::move(w));
    }

    scene.triangle_lights.resize(scene.meshes.size());
    for (std::uint32_t mi = 0; mi < scene.meshes.size(); ++mi) {
        const TriangleMesh& mesh = scene.meshes[mi];
        scene.bounds.expand(mesh.bounds());
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
            const Material& material = *scene.materials[mesh.face_materials[t]];
            if (!material.is_emissive()) continue;
            scene.emissive_triangles.push_back({mi, t});
            std::unique_ptr<Light> light = registry.make_area_light(mesh, t, material.emission);
            if (!light) continue;
            if (scene.triangle_lights[mi].empty()) scene.triangle_lights[mi].assign(mesh.triangles.size(), Scene::NoLight);
            scene.triangle_lights[mi][t] = static_cast<std::uint32_t>(scene.lights.size());
            light->where = "mesh '" + mesh.name + "', triangle " + std::to_string(t);
            scene.lights.push_back(std::move(light));
        }
    }
    read_lights(top, root, scene, registry);
    // Only now has every top-level key been asked for ("lights" by read_lights): collected
    // earlier, a scene with lights got the warning "unknown key 'lights' is ignored".
    for (std::string& w : top.unused_key_warnings()) scene.warnings.push_back(std::move(w));
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        scene.lights[i]->index = static_cast<std::uint32_t>(i);
        scene.lights[i]->preprocess(scene.bounds);
    }
    // The accelerator: the command line's, else the "accelerator" block's type, else the default.
    // The block's other keys are its settings, and apply only to the type it names.
    const nlohmann::json* block = top.has("accelerator") ? &root.at("accelerator") : nullptr;
    std::string block_type;
    if (block != nullptr) {
        const Parameters a = top.child("accelerator");
        block_type = a.get_string("type", "");
    }
    scene.accelerator_name = !options.accelerator.empty() ? options.accelerator
                             : !block_type.empty()        ? block_type
                                                          : registry.accelerators.default_name();
    const std::string accelerator_where = !options.accelerator.empty() ? "--accel" : !block_type.empty() ? top.where("accelerator") + "/type" : "default accelerator";
    registry.require(CapabilityKind::Accelerator, scene.accelerator_name, accelerator_where);
    check_options_apply(options.options, registry.options(), OptionTarget::Accelerator, scene.accelerator_name);
    const bool block_applies = block != nullptr && (block_type.empty() || block_type == scene.accelerator_name);
    const OptionParameters accelerator_options(block_applies ? block : nullptr, path, "/accelerator", base, options.options,
                                               registry.options(), OptionTarget::Accelerator);
    accelerator_options.parameters().get_string("type", "");
    scene.accelerator = registry.accelerators.make(scene.accelerator_name, accelerator_where, accelerator_options.parameters());
    for (std::string& w : accelerator_options.parameters().unused_key_warnings()) scene.warnings.push_back(std::move(w));
    scene.accelerator->build(scene.meshes);
    scene.has_alpha_masks = std::any_of(scene.materials.begin(), scene.materials.end(),
                                        [](const std::unique_ptr<Material>& m) { return m->alpha_mask != nullptr; });
    if (scene.has_alpha_masks) {
        for (const TriangleMesh& mesh : scene.meshes) {
            std::vector<std::uint8_t>& opaque = scene.opaque_triangles.emplace_back(mesh.triangles.size());
            for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
                opaque[t] = scene.materials[mesh.face_materials[t]]->alpha_mask == nullptr ? 1 : 0;
        }
    }
    scene.effects = compute_scene_effects(scene);
    scene.texture_footprint =
        scene.effects.textures && scene.camera ? registry.texture_footprint(&texture_settings) : nullptr;
    return scene;
}

std::unique_ptr<OptionParameters> integrator_options(const Scene& scene, const OptionValues& given,
                                                    const Registry& registry) {
    const std::string base = std::filesystem::path(scene.file).parent_path().string();
    return std::make_unique<OptionParameters>(&scene.defaults.integrator_options, scene.file, "/render", base, given,
                                              registry.options(), OptionTarget::Integrator);
}

}  // namespace freezeray
