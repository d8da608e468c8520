// The set of effects a scene calls for.
#include "freezeray/scene_effects.hpp"

#include "freezeray/bsdf.hpp"
#include "freezeray/scene.hpp"

#include <set>
#include <vector>

namespace freezeray {

SceneEffects compute_scene_effects(const Scene& scene) {
    SceneEffects effects;
    effects.area_emitters = !scene.emissive_triangles.empty();
    for (const auto& light : scene.lights) {
        effects.delta_lights |= is_delta_light(light->type());
        effects.environment |= light->type() == LightType::Infinite;
    }
    std::set<std::uint32_t> used;  // only materials some triangle uses count
    for (const TriangleMesh& mesh : scene.meshes) used.insert(mesh.face_materials.begin(), mesh.face_materials.end());
    for (std::uint32_t index : used) {
        const Material& m = *scene.materials[index];
        const std::uint32_t flags = m.flags();
        effects.diffuse |= has_flag(flags, BSDF_Diffuse);
        effects.glossy |= has_flag(flags, BSDF_Glossy);
        effects.specular |= has_flag(flags, BSDF_Specular);
        effects.transmission |= has_flag(flags, BSDF_Transmission);
        effects.textures |= m.is_textured();
    }
    return effects;
}

std::string SceneEffects::describe() const {
    std::string text;
    auto line = [&](bool present, const char* name) { text += std::string("  ") + (present ? "[x] " : "[ ] ") + name + "\n"; };
    line(area_emitters, "area emitters (emissive triangles)");
    line(delta_lights, "delta lights (point, spot, directional)");
    line(environment, "environment lighting");
    line(textures, "textured material parameters");
    line(diffuse, "diffuse reflection");
    line(glossy, "glossy (rough) scattering");
    line(specular, "specular (delta) scattering");
    line(transmission, "transmission");
    return text;
}

std::string describe_work_per_ray(const Scene& scene) {
    std::string text;
    auto line = [&](bool done, const std::string& work, const std::string& why) {
        text += std::string("  ") + (done ? "[x] " : "[ ] ") + work + " (" + why + ")\n";
    };
    line(scene.environment != nullptr, "environment lookup when a ray leaves the scene",
         scene.environment != nullptr ? "the scene has an environment light" : "no environment light: such a ray adds nothing");
    line(scene.has_alpha_masks, "alpha-mask test at hits and along shadow rays",
         scene.has_alpha_masks ? "some material has an alpha mask with holes"
                               : "no alpha mask: queries go straight to the accelerator");
    line(scene.effects.textures, "texel reads for material parameters",
         scene.effects.textures ? "some parameter is textured" : "every parameter is a constant");
    line(scene.texture_footprint != nullptr, "the pixel's footprint in texture space at textured hits",
         scene.texture_footprint != nullptr ? "the texture layout filters over it"
         : scene.effects.textures ? "the texture layout reads at the point"
                                  : "nothing is textured");
    return text;
}

}  // namespace freezeray
