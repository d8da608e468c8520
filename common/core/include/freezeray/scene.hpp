// A loaded scene: world-space meshes, materials, the camera, the accelerator, and the set of
// effects it calls for.
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/camera.hpp"
#include "freezeray/capability_choice.hpp"
#include "freezeray/light.hpp"
#include "freezeray/material.hpp"
#include "freezeray/mesh.hpp"
#include "freezeray/options.hpp"
#include "freezeray/scene_effects.hpp"
#include "freezeray/texture_storage.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace freezeray {

class Registry;

// Render defaults a scene may state in its "render" block; command-line options override them.
struct RenderDefaults {
    std::string integrator;          // empty: the renderer's best suited one
    std::uint64_t samples_per_pixel = 16;
    int max_depth = 0;               // 0: the integrator's default
    std::uint64_t seed = 0;
    // The capabilities of the kinds chosen per run that the block names, by kind (its "sampler",
    // "light_sampler"); a kind absent: the renderer's default.
    Selections named;
    // The block's keys that registered integrator options read: the integrator's factory reads
    // and checks them (integrator_options below).
    nlohmann::json integrator_options = nlohmann::json::object();
};

// One emissive triangle (an area light made of triangles).
struct EmissiveTriangle {
    std::uint32_t mesh;
    std::uint32_t triangle;
};

class Scene {
public:
    std::string file;                           // the scene's JSON file
    std::vector<TriangleMesh> meshes;           // world space
    std::vector<std::unique_ptr<Material>> materials;
    std::vector<EmissiveTriangle> emissive_triangles;
    // Every light: one area light per emissive triangle (when a chapter registered area lights),
    // then the "lights" of the scene file in their order. Light::index is the position here.
    std::vector<std::unique_ptr<Light>> lights;
    const Light* environment = nullptr;         // the infinite light, if any (at most one)
    CameraDescription camera_description;
    std::unique_ptr<const Camera> camera;       // made by the registered camera the scene names
    std::string camera_type;                    // its name ("pinhole")
    std::unique_ptr<Accelerator> accelerator;
    std::string accelerator_name;               // the registered accelerator it was built with
    // The accelerator is made with the scene and built over its meshes after it (the scene
    // builder's build_accelerator), on its own clock; `info` builds it only when it must trace rays.
    bool accelerator_built = false;
    double accelerator_build_seconds = 0.0;
    std::string texture_layout;                 // the layout its image textures are stored in (may be empty)
    // Every image texture its materials use (each file and encoding once), for `info`.
    std::vector<std::shared_ptr<const TextureStorage>> textures;
    std::size_t texture_memory_bytes() const {
        std::size_t bytes = 0;
        for (const auto& texture : textures) bytes += texture->memory_bytes();
        return bytes;
    }
    SceneEffects effects;
    Bounds3 bounds;
    RenderDefaults defaults;
    std::vector<std::string> warnings;          // printed by the command line after loading

    // The closest hit along the ray, and whether anything blocks it. Surfaces whose alpha mask
    // cuts them out where the ray meets them are passed through (scene.cpp).
    // The hit on a textured material carries the footprint of a pixel in texture space when
    // the scene's texture layouts read it (texture_footprint).
    std::optional<Hit> intersect(const Ray& ray) const {
        std::optional<Hit> hit = has_alpha_masks ? intersect_through_cutouts(ray) : accelerator->intersect(ray);
        if (hit && texture_footprint != nullptr && materials[hit->material]->is_textured())
            texture_footprint(*hit, meshes[hit->mesh], *camera);
        return hit;
    }
    bool occluded(const Ray& ray) const {
        return has_alpha_masks ? occluded_through_cutouts(ray) : accelerator->occluded(ray);
    }
    bool has_alpha_masks = false;               // some material has an alpha mask (set by load_scene)
    // With alpha masks: per mesh and triangle, 1 where the triangle's material has no mask, so
    // that it blocks every ray that meets it (set by load_scene; see occluded_through_cutouts).
    TriangleFlags opaque_triangles;
    // How hits on textured materials learn the pixel's footprint: the scene has textures, a
    // camera, and a texture layout that filters by footprint gives it
    // (Registry::texture_footprint; set by load_scene). Null for chapters 02-07's layout, which
    // looks up at the point, so their hits skip the footprint's work.
    TextureFootprint texture_footprint = nullptr;
    const Material& material(const Hit& hit) const { return *materials[hit.material]; }

    // Radiance arriving along a ray that leaves the scene: the environment's, or black.
    Spectrum environment_radiance(const Ray& ray) const {
        return environment != nullptr ? environment->le(ray.direction) : Spectrum(0.0f);
    }

    // The area light of the emissive triangle a ray hit; null when the triangle does not emit
    // or area lights are not registered.
    const Light* area_light(const Hit& hit) const {
        if (hit.mesh >= triangle_lights.size() || triangle_lights[hit.mesh].empty()) return nullptr;
        const std::uint32_t index = triangle_lights[hit.mesh][hit.triangle];
        return index == NoLight ? nullptr : lights[index].get();
    }

    std::size_t triangle_count() const;

    // Per mesh, per triangle: the index of its area light in `lights`, or NoLight. A mesh without
    // emitters has an empty vector.
    static constexpr std::uint32_t NoLight = 0xffffffffu;
    std::vector<std::vector<std::uint32_t>> triangle_lights;

private:
    std::optional<Hit> intersect_through_cutouts(const Ray& ray) const;
    bool occluded_through_cutouts(const Ray& ray) const;
};

// Computes the set of effects from the materials and emitters (called by load_scene).
SceneEffects compute_scene_effects(const Scene& scene);

}  // namespace freezeray
