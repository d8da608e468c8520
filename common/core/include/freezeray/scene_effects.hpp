// The set of effects a scene calls for, computed once at load so that the renderer pays only
// for what the scene contains.
#pragma once

#include <string>

namespace freezeray {

class Scene;

struct SceneEffects {
    bool area_emitters = false;     // emissive triangles
    bool delta_lights = false;      // point, spot, directional lights (chapter 03)
    bool environment = false;       // an environment map or constant background (chapter 03)
    bool textures = false;          // any textured material parameter (chapter 02)
    bool diffuse = false;           // any diffuse lobe
    bool glossy = false;            // any glossy (rough) lobe
    bool specular = false;          // any delta (mirror, smooth glass) lobe
    bool transmission = false;      // any transmissive lobe

    // A human-readable list, one effect per line, for `info`.
    std::string describe() const;
};

// The work a render does per ray that depends on what the scene contains, one line each, for
// `info`: "[x]" done, "[ ]" skipped, with the reason. Each line names a test the code makes
// (Scene::intersect, Scene::occluded, Scene::environment_radiance, the textures), so that a scene
// without an effect pays nothing for it.
std::string describe_work_per_ray(const Scene& scene);

}  // namespace freezeray
