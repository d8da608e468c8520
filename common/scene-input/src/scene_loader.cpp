// Loading a scene file: its reader (by extension), the builder, the accelerator's build.
#include "freezeray/scene_loader.hpp"

#include "freezeray/registry.hpp"
#include "freezeray/scene_readers.hpp"

#include <filesystem>

namespace freezeray {

Scene load_scene(const std::string& path, const Registry& registry, const SceneLoadOptions& options) {
    Scene scene = build_scene(read_scene_description(path), registry, options);
    if (options.build_accelerator) build_accelerator(scene);
    return scene;
}

std::unique_ptr<OptionParameters> integrator_options(const Scene& scene, const OptionValues& given,
                                                    const Registry& registry) {
    const std::string base = std::filesystem::path(scene.file).parent_path().string();
    return std::make_unique<OptionParameters>(&scene.defaults.integrator_options, scene.file, "/render", base, given,
                                              registry.options(), OptionTarget::Integrator);
}

}  // namespace freezeray
