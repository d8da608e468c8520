// Chapter 03's registrations.
#include "freezeray/ch03/register_chapter03.hpp"
#include "freezeray/ch02/register_chapter02.hpp"

#include "freezeray/ch03/area_light.hpp"
#include "freezeray/ch03/directional_light.hpp"
#include "freezeray/ch03/environment_light.hpp"
#include "freezeray/ch03/light_sampling_path_tracer.hpp"
#include "freezeray/ch03/point_light.hpp"
#include "freezeray/ch03/spot_light.hpp"
#include "freezeray/scene.hpp"

namespace freezeray {

namespace {

void add_path_tracer(Registry& registry, const std::string& name, const std::string& summary,
                     ch03::LightSamplingSettings variant) {
    // A variant with its own fixed light selection (pt-nee-uniform, pt-mis-uniform) takes no
    // light sampler.
    const IntegratorTraits traits{.samples_lights = true,
                                  .draws_from_sampler = true,
                                  .chooses_lights_per_point = !variant.selection_fixed};
    registry.integrators.add(name, 3, summary, {traits, [variant](const RenderSettings& settings, const Parameters&) {
                                                    ch03::LightSamplingSettings s = variant;
                                                    s.max_depth = settings.max_depth;
                                                    return std::make_unique<ch03::LightSamplingPathTracer>(s);
                                                }});
}

}  // namespace

void register_chapter03(Registry& registry) {
    register_chapter02(registry);  // chapters 01 to 02 first
    registry.add_area_light(3, "every emissive triangle, sampled by area", [](const TriangleMesh& mesh, std::uint32_t triangle,
                                                                              const Spectrum& emission) {
        return std::make_unique<ch03::TriangleLight>(mesh, triangle, emission);
    });
    registry.lights.add("point", 3, "point light: position, intensity", ch03::make_point_light);
    registry.lights.add("spot", 3, "spot light: position, look_at or direction, intensity, cone_angle_degrees, falloff_start_degrees",
                       ch03::make_spot_light);
    registry.lights.add("directional", 3, "parallel light from one direction: direction (of travel), irradiance",
                       ch03::make_directional_light);
    registry.lights.add("environment", 3, "equirectangular environment map: file, scale, rotate {axis, degrees}",
                       ch03::make_environment_map_light);
    registry.lights.add("constant", 3, "constant environment: radiance", ch03::make_constant_environment_light);

    using ch03::Combination;
    using ch03::LightSelection;
    using ch03::MisHeuristic;
    add_path_tracer(registry, "pt-nee", "path tracing with next-event estimation (one light sample per vertex, lights chosen by power)",
                    {Combination::NextEventEstimation, MisHeuristic::Power, LightSelection::Power, false, 0});
    add_path_tracer(registry, "pt-nee-uniform", "pt-nee choosing lights uniformly instead of by power",
                    {Combination::NextEventEstimation, MisHeuristic::Power, LightSelection::Uniform, true, 0});
    add_path_tracer(registry, "pt-mis", "path tracing combining light and BSDF sampling by MIS (power heuristic)",
                    {Combination::MultipleImportanceSampling, MisHeuristic::Power, LightSelection::Power, false, 0});
    add_path_tracer(registry, "pt-mis-balance", "pt-mis with the balance heuristic",
                    {Combination::MultipleImportanceSampling, MisHeuristic::Balance, LightSelection::Power, false, 0});
    add_path_tracer(registry, "pt-mis-uniform", "pt-mis choosing lights uniformly instead of by power",
                    {Combination::MultipleImportanceSampling, MisHeuristic::Power, LightSelection::Uniform, true, 0});
    registry.add_advice({"pt-mis", [](const Scene&, const AdviceRequest&) -> std::optional<std::string> {
                             return "light and BSDF sampling combined";
                         }});

    // Light samplers for pt-nee and pt-mis (`--light-sampler`); power is the default.
    registry.light_samplers.add("power", 3, "in proportion to each light's power, the same at every shading point",
                               [](const std::vector<std::unique_ptr<Light>>& lights, const Parameters&) {
                                   return std::make_unique<ch03::FixedLightSampler>(lights, LightSelection::Power);
                               });
    registry.light_samplers.add("uniform", 3, "every light with the same probability, at every shading point",
                               [](const std::vector<std::unique_ptr<Light>>& lights, const Parameters&) {
                                   return std::make_unique<ch03::FixedLightSampler>(lights, LightSelection::Uniform);
                               });
}

}  // namespace freezeray
