// Chapter 04's registrations.
#include "freezeray/ch04/register_chapter04.hpp"
#include "freezeray/ch03/register_chapter03.hpp"

#include "freezeray/ch04/bidirectional_path_tracer.hpp"
#include "freezeray/ch04/camera_importance.hpp"
#include "freezeray/ch04/light_tracer.hpp"
#include "freezeray/scene.hpp"

namespace freezeray {

namespace {

// A bidirectional sample belongs to a pixel (its camera subpath starts there): with a render's
// sampler (chapter 09), its three streams draw from the pixel's samples (pixel_sample_stream.hpp).
// Its film splats, so a saved render cannot go on.
constexpr IntegratorTraits BidirectionalTraits{.samples_lights = true, .draws_from_sampler = true, .resumable = false};

}  // namespace

void register_chapter04(Registry& registry) {
    register_chapter03(registry);  // chapters 01 to 03 first
    // The pinhole again, now with its importance (camera_importance.hpp): light paths connect to it.
    registry.cameras.add("pinhole", 4, "a pinhole with its importance, which light paths connect to",
                         [](const CameraDescription& description, const Parameters&) {
                             return std::make_unique<ch04::ImportancePinholeCamera>(description);
                         });
    registry.add_option({"--bdpt-strategies", "bdpt_strategies", OptionType::Text, OptionTarget::Integrator,
                         "write each strategy's image, weighted and unweighted, and their grids into this folder "
                         "(bidirectional path tracing)",
                         {"bdpt", "bdpt-balance"}, 4});
    registry.integrators.add("light-tracing", 4,
                            "light tracing: paths from the lights, every vertex connected to the camera and splatted "
                            "(bdpt's t = 1 strategies alone)",
                            // Its own streams; a splatting film keeps sums, not per-pixel samples.
                            {{.samples_lights = true, .resumable = false},
                             [](const RenderSettings& settings, const Parameters&) {
                                 ch04::LightTracingSettings s;
                                 s.max_depth = settings.max_depth;
                                 return std::make_unique<ch04::LightTracer>(s);
                             }});
    registry.integrators.add("bdpt", 4,
                            "bidirectional path tracing: camera and light subpaths joined in every way, combined by "
                            "MIS (power heuristic)",
                            {BidirectionalTraits, [](const RenderSettings& settings, const Parameters& options) {
                                 return std::make_unique<ch04::BidirectionalPathTracer>(ch04::read_bidirectional_settings(
                                     options, settings.max_depth, ch03::MisHeuristic::Power));
                             }});
    registry.integrators.add("bdpt-balance", 4, "bidirectional path tracing with the balance heuristic",
                            {BidirectionalTraits, [](const RenderSettings& settings, const Parameters& options) {
                                 return std::make_unique<ch04::BidirectionalPathTracer>(ch04::read_bidirectional_settings(
                                     options, settings.max_depth, ch03::MisHeuristic::Balance));
                             }});
    registry.add_advice({"bdpt", [](const Scene& scene, const AdviceRequest&) -> std::optional<std::string> {
                             const SceneEffects& e = scene.effects;
                             if ((e.specular || e.transmission) && (e.area_emitters || e.delta_lights))
                                 return "caustics through specular surfaces are found from the light side";
                             return std::nullopt;
                         }});
}

}  // namespace freezeray
