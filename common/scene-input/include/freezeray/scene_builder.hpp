// Making a Scene of a SceneDescription, whatever file it was read from: the camera, the texture
// layout, the materials, the render defaults, the area and other lights and the accelerator, each
// through the registry and each kind chosen by one rule (capability_choice.hpp). The accelerator
// is made here and built apart (build_accelerator), timed on its own.
#pragma once

#include "freezeray/capability_choice.hpp"
#include "freezeray/options.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_description.hpp"

namespace freezeray {

class Registry;

// What the command line sets of a scene.
struct SceneLoadOptions {
    // The selectors of the kinds chosen once for the scene (`--accel`, `--texture-layout`), over
    // the scene's blocks ("accelerator", "textures"), over the defaults.
    Selections selections;
    // Registered options given on the command line; those of accelerators and texture layouts
    // are used here, over the scene's "accelerator" and "textures" blocks.
    OptionValues options;
    // Overrides of the scene's camera resolution (0: keep).
    int width = 0;
    int height = 0;
    // Build the accelerator after building the scene (load_scene); `info` does not, unless a rule
    // of its suggestion traces rays.
    bool build_accelerator = true;
};

// Everything but the accelerator's build. Throws InputError naming the file and JSON path, or the
// flag, of anything wrong.
Scene build_scene(SceneDescription description, const Registry& registry, const SceneLoadOptions& options = {});

// Builds the scene's accelerator over its meshes; Scene::accelerator_build_seconds says how long it took.
void build_accelerator(Scene& scene);

}  // namespace freezeray
