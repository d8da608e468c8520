// Loading a scene file: the reader of its format makes a SceneDescription (scene_readers.hpp),
// the builder a Scene of it through the registry (scene_builder.hpp), and the accelerator is
// built last.
#pragma once

#include "freezeray/options.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_builder.hpp"

#include <memory>
#include <string>

namespace freezeray {

class Registry;

// Reads, builds and (unless options say otherwise) builds the accelerator. Throws InputError
// naming the file and JSON path, or file:line, of anything wrong.
Scene load_scene(const std::string& path, const Registry& registry, const SceneLoadOptions& options = {});

// The parameters of the scene's integrator: its "render" block's integrator options with the
// command-line values in `given` over them.
std::unique_ptr<OptionParameters> integrator_options(const Scene& scene, const OptionValues& given,
                                                    const Registry& registry);

}  // namespace freezeray
