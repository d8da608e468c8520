// The set of effects a scene calls for.
#include "freezeray/scene_effects.hpp"

#include "freezeray/bsdf.hpp"
#include "freezeray/registry.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/sds_probe.hpp"

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
    line(scene.texture_footprints, "the pixel's footprint in texture space at textured hits",
         scene.texture_footprints ? "the texture layout filters over it"
         : scene.effects.textures ? "the texture layout reads at the point"
                                  : "nothing is textured");
    return text;
}

IntegratorSuggestion SceneEffects::suggest_integrator(const Registry& registry, double sds_share) const {
    if (!area_emitters && !environment && !delta_lights) return {"", "the scene has no light and renders black"};
    // The candidates, best first; the first one the renderer has is the suggestion.
    std::vector<IntegratorSuggestion> candidates;
    if (sds_share > SdsShareLimit)
        candidates.push_back({"mlt", "much of the image is lit through a specular surface and seen through one: only a "
                                     "camera path that hits the light makes those paths, and a Markov chain explores them "
                                     "once found"});
    if ((specular || transmission) && (area_emitters || delta_lights))
        candidates.push_back({"bdpt", "caustics through specular surfaces are found from the light side"});
    candidates.push_back({"pt-mis", "light and BSDF sampling combined"});
    if (!delta_lights) {
        candidates.push_back({"pt-is", "BSDF importance sampling"});
        candidates.push_back({"pt-naive", specular ? "renders specular surfaces black; importance sampling comes in chapter 02"
                                                   : "the only integrator of chapter 01"});
    }
    for (const IntegratorSuggestion& candidate : candidates)
        if (registry.has(CapabilityKind::Integrator, candidate.name)) return candidate;
    return {"", "point, spot and directional lights are found only by light sampling, which comes in chapter 03"};
}

}  // namespace freezeray
