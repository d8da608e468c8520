// Chapter 02's registrations.
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/ch01/register_chapter01.hpp"

#include "freezeray/ch02/alpha_mask.hpp"
#include "freezeray/ch02/materials.hpp"
#include "freezeray/ch02/path_tracer.hpp"
#include "freezeray/ch02/linear_layout.hpp"
#include "freezeray/error.hpp"
#include "freezeray/scene.hpp"

#include <string>
#include <vector>

namespace freezeray {

namespace {

// The materials of chapter 02 with the summary `--help` and `info` print.
struct MaterialEntry {
    const char* name;
    const char* summary;
    std::unique_ptr<Material> (*make)(const Parameters&, const MaterialContext&);
};

std::unique_ptr<Material> make_mix_part(const Parameters& p, const MaterialContext& context);

const MaterialEntry chapter02_materials[] = {
    {"diffuse", "Lambertian reflector, cosine-sampled: albedo or albedo_texture (MTL Kd, map_Kd)",
     ch02::make_diffuse_material},
    {"mirror", "perfect mirror: reflectance at every angle", ch02::make_mirror_material},
    {"conductor", "smooth metal: preset material, or eta and k, tinted by specular_reflectance (MTL Ks)",
     [](const Parameters& p, const MaterialContext& c) { return ch02::make_conductor_material(p, c, false); }},
    {"roughconductor", "rough metal (GGX microfacets): as conductor, plus roughness",
     [](const Parameters& p, const MaterialContext& c) { return ch02::make_conductor_material(p, c, true); }},
    {"dielectric", "smooth glass: ior (MTL Ni)", [](const Parameters& p, const MaterialContext& c) { return ch02::make_dielectric_material(p, c, false); }},
    {"roughdielectric", "rough glass (GGX microfacets): ior, roughness",
     [](const Parameters& p, const MaterialContext& c) { return ch02::make_dielectric_material(p, c, true); }},
    {"plastic", "diffuse base under a smooth dielectric coating: albedo, ior",
     [](const Parameters& p, const MaterialContext& c) { return ch02::make_plastic_material(p, c, false); }},
    {"roughplastic", "diffuse base under a rough coating (GGX microfacets): albedo, ior, roughness",
     [](const Parameters& p, const MaterialContext& c) { return ch02::make_plastic_material(p, c, true); }},
    {"mix", "two materials blended by a weight: first, second, weight",
     [](const Parameters& p, const MaterialContext& c) { return ch02::make_mix_material(p, c, make_mix_part); }},
};

// A part of a mix material: any material of this chapter, described inline.
std::unique_ptr<Material> make_mix_part(const Parameters& p, const MaterialContext& context) {
    const std::string type = p.require_string("type");
    std::vector<std::string> names;
    for (const MaterialEntry& entry : chapter02_materials) {
        if (type == entry.name) {
            std::unique_ptr<Material> material = entry.make(p, context);
            material->type = type;
            return material;
        }
        names.emplace_back(entry.name);
    }
    throw InputError(p.where("type"), "unknown material '" + type + "' (did you mean '" + nearest_name(type, names) +
                                          "'?); a part of a mix is one of chapter 02's materials");
}

}  // namespace

void register_chapter02(Registry& registry) {
    register_chapter01(registry);  // chapter 01 first
    // Every material of this chapter may have an alpha mask (cut-outs), read beside its own parameters.
    for (const MaterialEntry& entry : chapter02_materials)
        registry.materials.add(entry.name, 2, entry.summary, [make = entry.make](const Parameters& p, const MaterialContext& c) {
            std::unique_ptr<Material> material = make(p, c);
            material->alpha_mask = ch02::read_alpha_mask(p, c);
            return material;
        });
    registry.texture_layouts.add("linear", 2, "rows of texels one after another, as the image file stores them",
                                [](const Parameters&) -> TextureStorageMaker {
                                    // Looked up at the point: no footprint.
                                    return {[](const Image& image) { return std::make_shared<ch02::LinearTextureStorage>(image); },
                                            nullptr};
                                });
    registry.integrators.add("pt-is", 2, "path tracing with BSDF importance sampling and Russian roulette",
                            {{.draws_from_sampler = true},
                             [](const RenderSettings& settings, const Parameters&) {
                                 return std::make_unique<ch02::ImportanceSampledPathTracer>(settings.max_depth);
                             }});
    registry.add_advice({"pt-is", [](const Scene& scene, const AdviceRequest&) -> std::optional<std::string> {
                             if (scene.effects.delta_lights) return std::nullopt;  // found only by light sampling
                             return "BSDF importance sampling";
                         }});
}

}  // namespace freezeray
