// Chapter 01's registrations.
#include "freezeray/ch01/register_chapter01.hpp"

#include "freezeray/ch01/lambertian.hpp"
#include "freezeray/ch01/naive_path_tracer.hpp"
#include "freezeray/course_catalogue.hpp"
#include "freezeray/scene.hpp"

namespace freezeray {

void register_chapter01(Registry& registry) {
    // Chapter 01 opens the course: the registry learns its table of contents, so that a later
    // chapter's capability is refused with the chapter that introduces it.
    registry.set_catalogue(course_catalogue());
    registry.materials.add("diffuse", 1, "Lambertian reflector: albedo (MTL Kd)",
                          [](const Parameters& p, const MaterialContext&) {
                              const Spectrum albedo = p.get_spectrum("albedo", Spectrum(0.5f));
                              for (int c = 0; c < 3; ++c) p.check_range("albedo", albedo[c], 0.0f, 1.0f);
                              return std::make_unique<ch01::DiffuseMaterial>(albedo);
                          });
    registry.integrators.add("pt-naive", 1, "naive path tracing: uniform hemisphere sampling, emission found by hitting it",
                            {{.draws_from_sampler = true},
                             [](const RenderSettings& settings, const Parameters&) {
                                 return std::make_unique<ch01::NaivePathTracer>(settings.max_depth);
                             }});
    // Naive path tracing finds emitters by hitting them, so never a point, spot or directional light.
    registry.add_advice({"pt-naive", [](const Scene& scene, const AdviceRequest&) -> std::optional<std::string> {
                             if (scene.effects.delta_lights) return std::nullopt;
                             return scene.effects.specular
                                        ? "renders specular surfaces black; importance sampling comes in chapter 02"
                                        : "the only integrator of chapter 01";
                         }});
}

}  // namespace freezeray
