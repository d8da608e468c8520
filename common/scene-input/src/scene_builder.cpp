// Building a Scene from its description (scene_builder.hpp): every capability made through the
// registry, every kind chosen by one rule (capability_choice.hpp).
#include "freezeray/scene_builder.hpp"

#include "freezeray/error.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/registry.hpp"

#include <algorithm>
#include <chrono>

namespace freezeray {

namespace {

Parameters parameters_of(const ParameterBlock& block, const std::string& base_directory) {
    Parameters parameters(block.json, block.file, block.path, base_directory);
    for (const std::string& key : block.taken) parameters.has(key);  // asked by the reader
    return parameters;
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

// The lights the description lists: analytic lights and the environment, made by the registry
// (chapter 03 registers them). At most one light may be at infinity.
void build_lights(const SceneDescription& description, Scene& scene, const Registry& registry) {
    for (const ParameterBlock& block : description.lights) {
        const Parameters p = parameters_of(block, description.base_directory);
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

// The "render" block: the run's defaults, the per-run kinds it names, and the keys of the
// integrators' options (the integrator's factory reads and checks them).
void read_render_defaults(const SceneDescription& description, Scene& scene, const Registry& registry) {
    if (!description.render.given) return;
    const Parameters r = parameters_of(description.render, description.base_directory);
    scene.defaults.integrator = r.get_string("integrator", "");
    const int spp = r.get_int("spp", 16);
    if (spp < 1) throw InputError(r.where("spp"), "must be at least 1");
    scene.defaults.samples_per_pixel = static_cast<std::uint64_t>(spp);
    scene.defaults.max_depth = r.get_int("max_depth", 0);
    if (scene.defaults.max_depth < 0) throw InputError(r.where("max_depth"), "must not be negative");
    scene.defaults.seed = static_cast<std::uint64_t>(r.get_int("seed", 0));
    for (CapabilityKind kind : all_capability_kinds) {
        const KindDescription& d = kind_description(kind);
        if (!d.per_run || std::string(d.scene_block) != "render") continue;
        const std::string name = r.get_string(d.scene_key, "");
        if (name.empty()) continue;
        registry.require(kind, name, r.where(d.scene_key));
        scene.defaults.named[kind] = name;
    }
    for (const OptionDeclaration& d : registry.options())
        if (d.target == OptionTarget::Integrator && r.has(d.key)) scene.defaults.integrator_options[d.key] = r.json().at(d.key);
    for (std::string& w : r.unused_key_warnings()) scene.warnings.push_back(std::move(w));
}

// An area light for every emissive triangle (from chapter 03, which registers them).
void build_area_lights(Scene& scene, const Registry& registry) {
    scene.triangle_lights.resize(scene.meshes.size());
    for (std::uint32_t mi = 0; mi < scene.meshes.size(); ++mi) {
        const TriangleMesh& mesh = scene.meshes[mi];
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
}

// The accelerator, chosen as every kind is and made with its settings, not yet built. The
// block's other keys are its settings, and apply only to the type it names.
void make_accelerator(const SceneDescription& description, Scene& scene, const Registry& registry,
                      const SceneLoadOptions& options) {
    std::string block_type;
    if (description.accelerator.given)
        block_type = parameters_of(description.accelerator, description.base_directory).get_string("type", "");
    const CapabilityChoice accelerator =
        choose_capability(registry.accelerators, options.selections, block_type, description.file + ": /accelerator/type");
    scene.accelerator_name = accelerator.name;
    check_options_apply(options.options, registry.options(), OptionTarget::Accelerator, scene.accelerator_name);
    const bool block_applies = description.accelerator.given && (block_type.empty() || block_type == scene.accelerator_name);
    const OptionParameters settings(block_applies ? &description.accelerator.json : nullptr, description.file, "/accelerator",
                                    description.base_directory, options.options, registry.options(), OptionTarget::Accelerator);
    settings.parameters().get_string("type", "");
    scene.accelerator = registry.accelerators.make(scene.accelerator_name, accelerator.where, settings.parameters());
    for (std::string& w : settings.parameters().unused_key_warnings()) scene.warnings.push_back(std::move(w));
}

}  // namespace

Scene build_scene(SceneDescription description, const Registry& registry, const SceneLoadOptions& options) {
    Scene scene;
    scene.file = description.file;

    // The camera: the registered type the block names, else the default (the pinhole).
    scene.camera_description = description.camera;
    if (options.width > 0) scene.camera_description.width = options.width;
    if (options.height > 0) scene.camera_description.height = options.height;
    const Parameters camera_block = parameters_of(description.camera_block, description.base_directory);
    const CapabilityChoice camera = choose_capability(registry.cameras, options.selections,
                                                      camera_block.get_string("type", ""), camera_block.where("type"));
    scene.camera_type = camera.name;
    scene.camera = registry.cameras.make(camera.name, camera.where, scene.camera_description, camera_block);
    for (std::string& w : camera_block.unused_key_warnings()) scene.warnings.push_back(std::move(w));

    // The layout image textures are stored in (none before chapter 02, which has no image
    // textures). Its settings are read (and checked) here, whether or not the scene has image
    // textures.
    const OptionParameters textures(description.textures.given ? &description.textures.json : nullptr, description.file,
                                    "/textures", description.base_directory, options.options, registry.options(),
                                    OptionTarget::Textures);
    const Parameters& texture_settings = textures.parameters();
    const CapabilityChoice layout = choose_capability(registry.texture_layouts, options.selections,
                                                      texture_settings.get_string("layout", ""), texture_settings.where("layout"));
    scene.texture_layout = layout.name;
    if (!scene.texture_layout.empty()) registry.texture_storage_maker(scene.texture_layout, layout.where, &texture_settings);
    for (std::string& w : texture_settings.unused_key_warnings()) scene.warnings.push_back(std::move(w));
    // Then what the reader noticed (meshes, transforms, materials' files, unknown keys).
    for (std::string& w : description.warnings) scene.warnings.push_back(std::move(w));

    // The materials, in the order the description lists them (the meshes' indices).
    const MaterialContext material_context{registry, scene.texture_layout, &texture_settings, &scene.textures};
    for (const MaterialDescription& m : description.materials)
        scene.materials.push_back(build_material(m.name, m.parameters.json, m.parameters.file, m.parameters.path,
                                                 description.base_directory, material_context, scene.warnings));
    scene.meshes = std::move(description.meshes);
    for (const TriangleMesh& mesh : scene.meshes) scene.bounds.expand(mesh.bounds());

    read_render_defaults(description, scene, registry);
    build_area_lights(scene, registry);
    build_lights(description, scene, registry);
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        scene.lights[i]->index = static_cast<std::uint32_t>(i);
        scene.lights[i]->preprocess(scene.bounds);
    }
    make_accelerator(description, scene, registry, options);
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

void build_accelerator(Scene& scene) {
    const auto start = std::chrono::steady_clock::now();
    scene.accelerator->build(scene.meshes);
    scene.accelerator_build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    scene.accelerator_built = true;
}

}  // namespace freezeray
