// Helpers for tests that render.
#include "test_scenes.hpp"

#include "freezeray/run_plan.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/complete_renderer.hpp"
#include "freezeray/error.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/progress.hpp"

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

#ifndef FREEZERAY_SOURCE_DIR
#define FREEZERAY_SOURCE_DIR "."
#endif

namespace freezeray::testing {

std::string scene_path(const std::string& relative) { return std::string(FREEZERAY_SOURCE_DIR) + "/scenes/" + relative; }

std::string test_data_path(const std::string& relative) {
    return std::string(FREEZERAY_SOURCE_DIR) + "/tests/data/" + relative;
}

std::optional<std::string> shared_scenes_folder() {
    const std::string folder = freezeray::shared_scenes_folder();  // the one the scene files' names use
    std::error_code error;
    if (std::filesystem::is_directory(folder, error)) return folder;
    return std::nullopt;
}

const Registry& full_registry() {
    static const Registry registry = make_complete_registry("freezeray");
    return registry;
}

std::string scene_load_error(const std::string& path, const Registry& registry) {
    try {
        load_scene(path, registry);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

RenderResult render(const TestRender& request) {
    SceneLoadOptions options;
    options.width = request.width;
    options.height = request.height;
    if (!request.accelerator.empty()) options.selections[CapabilityKind::Accelerator] = request.accelerator;
    for (const auto& [key, value] : request.accelerator_settings.items()) options.options.values[key] = value;
    for (const auto& [key, value] : request.texture_settings.items()) {
        if (key == "layout")  // --texture-layout, the kind's selector
            options.selections[CapabilityKind::TextureLayout] = value.get<std::string>();
        else
            options.options.values[key] = value;
    }
    const Scene scene = load_scene(request.scene, full_registry(), options);
    RenderSettings settings;
    settings.samples_per_pixel = request.samples_per_pixel;
    settings.seed = request.seed;
    settings.threads = request.threads;
    settings.max_depth = request.max_depth > 0 ? request.max_depth : scene.defaults.max_depth;
    // The chapters' own options, as the command line would give them.
    OptionValues given;
    if (request.strategy_images) given.values["bdpt_strategies"] = std::filesystem::temp_directory_path().string();
    if (request.mlt_bootstrap > 0) given.values["mlt_bootstrap"] = request.mlt_bootstrap;
    if (request.mlt_chains > 0) given.values["mlt_chains"] = request.mlt_chains;
    const auto chapter_options = integrator_options(scene, given, full_registry());
    // "integrator@sampler", "integrator@light_sampler", or both, as compare's runs name them.
    const RunName run = parse_run_name(request.integrator, full_registry());
    const std::string& integrator_name = run.integrator;
    if (const auto it = run.named.find(CapabilityKind::Sampler); it != run.named.end())
        settings.sampler = full_registry().samplers.make(it->second, "test", Parameters::none());
    if (const auto it = run.named.find(CapabilityKind::LightSampler); it != run.named.end())
        settings.light_sampler = full_registry().light_samplers.make(it->second, "test", scene.lights, Parameters::none());
    const auto integrator = full_registry().integrators.make(integrator_name, "test", settings, chapter_options->parameters());
    Progress quiet(true);
    return integrator->render(scene, settings, quiet);
}

TemporaryFolder::TemporaryFolder() {
    static std::atomic<int> counter{0};
    std::random_device device;
    const auto base = std::filesystem::temp_directory_path();
    path_ = (base / ("freezeray-test-" + std::to_string(device()) + "-" + std::to_string(counter++))).string();
    std::filesystem::create_directories(path_);
}

std::string TemporaryFolder::write(const std::string& name, const std::string& text) const {
    const std::string path = file(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TemporaryFolder::~TemporaryFolder() {
    std::error_code error;
    std::filesystem::remove_all(path_, error);
}

}  // namespace freezeray::testing
