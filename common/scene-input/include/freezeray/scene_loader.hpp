// Reading a scene file: the JSON scene format (scenes/README.md) with its OBJ/MTL meshes, made
// into a Scene through the registry.
#pragma once

#include "freezeray/options.hpp"
#include "freezeray/scene.hpp"

#include <memory>
#include <string>

namespace freezeray {

class Registry;

struct SceneLoadOptions {
    // The accelerator (`--accel`); empty: the scene's "accelerator" block, else the registry's
    // default.
    std::string accelerator;
    // Registered options given on the command line; those of accelerators and texture layouts
    // are used here, over the scene's "accelerator" and "textures" blocks.
    OptionValues options;
    // Overrides of the scene's camera resolution (0: keep).
    int width = 0;
    int height = 0;
};

// Loads a JSON scene (format: scenes/README.md), its OBJ/MTL meshes and materials, builds the
// accelerator and computes the effects. Throws InputError naming the file and JSON path or
// file:line of anything wrong.
Scene load_scene(const std::string& path, const Registry& registry, const SceneLoadOptions& options = {});

// The parameters of the scene's integrator: its "render" block's integrator options with the
// command-line values in `given` over them.
std::unique_ptr<OptionParameters> integrator_options(const Scene& scene, const OptionValues& given,
                                                    const Registry& registry);

}  // namespace freezeray
