// Bidirectional path tracing (book chapter 04; Veach 1997, chapter 10; pbrt-v3, section 16.3).
#include "freezeray/ch04/bidirectional_path_tracer.hpp"

#include "freezeray/ch02/path_tracer.hpp"
#include "freezeray/ch04/bdpt_mis_weight.hpp"
#include "freezeray/ch04/pixel_sample_stream.hpp"
#include "freezeray/ch04/strategy_images.hpp"
#include "freezeray/error.hpp"
#include "freezeray/ch04/subpaths.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace freezeray::ch04 {

// BOOK(connect-strategy)
StrategyContribution connect_strategy(const Scene& scene, const ch03::FixedLightSampler& lights, ch03::MisHeuristic heuristic,
                                      const PathVertex* light, int s, const PathVertex* camera, int t,
                                      SampleStream& samples) {
    StrategyContribution result;
    // A camera subpath that escaped ends on the environment: only s = 0 can use that vertex.
    if (t > 1 && s != 0 && camera[t - 1].type == VertexType::Light) return result;

    PathVertex sampled;  // the vertex an s = 1 or t = 1 strategy samples at the connection
    const PathVertex* sampled_vertex = nullptr;
    Spectrum L(0.0f);
    if (s == 0) {
        // The camera subpath found emission by itself.
        const PathVertex& pt = camera[t - 1];
        if (pt.is_light()) L = pt.beta * vertex_le(scene, pt, camera[t - 2]);
    } else if (t == 1) {
        // Connect the light subpath to the camera (light tracing), landing at another pixel.
        const PathVertex& qs = light[s - 1];
        if (!qs.connectible()) return result;
        if (s == 1 && qs.light->type() != LightType::Area) return result;  // see the chapter's README
        const std::optional<CameraImportanceSample> camera_sample = scene.camera->sample_wi(qs.position, Vec2(0.5f));
        if (!camera_sample || camera_sample->pdf <= 0.0f || camera_sample->importance <= 0.0f) return result;
        sampled.type = VertexType::Camera;
        sampled.position = camera_sample->position;
        sampled.beta = Spectrum(camera_sample->importance / camera_sample->pdf);
        if (s == 1) {
            // The light seen directly: a one-sided Lambertian emitter sends Le towards the camera.
            const float cos_light = glm::dot(qs.geometric_normal, camera_sample->wi);
            if (cos_light <= 0.0f) return result;
            L = qs.beta * sampled.beta * cos_light;
        } else {
            L = qs.beta * vertex_f(qs, sampled) * sampled.beta * std::abs(glm::dot(camera_sample->wi, qs.frame.n));
        }
        if (is_black(L) || !mutually_visible(scene, qs, sampled)) return result;
        result.at_raster = true;
        result.raster_position = camera_sample->raster_position;
        sampled_vertex = &sampled;
    } else if (s == 1) {
        // Sample a point on a light (chapter 03's next-event estimation) for the camera subpath.
        const PathVertex& pt = camera[t - 1];
        const float u_select = samples.next_float();
        const Vec2 u_light = samples.next_2d();
        if (!pt.connectible()) return result;
        const std::optional<ch03::FixedLightSampler::Choice> choice = lights.sample(u_select);
        if (!choice || choice->probability <= 0.0f) return result;
        const std::optional<LightSample> light_sample = choice->light->sample_li(pt.position, u_light);
        if (!light_sample || light_sample->pdf <= 0.0f || is_black(light_sample->radiance)) return result;
        const LightType type = choice->light->type();
        sampled.type = VertexType::Light;
        sampled.transport = Transport::Importance;
        sampled.light = choice->light;
        sampled.infinite = type == LightType::Infinite || type == LightType::DeltaDirection;
        sampled.position = sampled.infinite ? pt.position + light_sample->wi : light_sample->position;
        sampled.geometric_normal = light_sample->normal;
        sampled.beta = light_sample->radiance / (choice->probability * light_sample->pdf);
        sampled.pdf_fwd = light_origin_pdf(lights, sampled, pt);
        L = pt.beta * vertex_f(pt, sampled) * sampled.beta * std::abs(glm::dot(light_sample->wi, pt.frame.n));
        if (is_black(L) || !mutually_visible(scene, pt, sampled)) return result;
        sampled_vertex = &sampled;
    } else {
        // Join the two end vertices with a deterministic segment.
        const PathVertex& qs = light[s - 1];
        const PathVertex& pt = camera[t - 1];
        if (!qs.connectible() || !pt.connectible()) return result;
        L = qs.beta * vertex_f(qs, pt) * vertex_f(pt, qs) * pt.beta;
        if (is_black(L)) return result;
        L *= geometry_term(scene, qs, pt);
    }
    if (is_black(L)) return result;
    result.unweighted = L;
    result.weight = bdpt_mis_weight(scene, lights, heuristic, light, s, camera, t, sampled_vertex);
    return result;
}
// END BOOK

BidirectionalPathTracer::BidirectionalPathTracer(const BidirectionalSettings& settings) : settings_(settings) {
    if (settings_.max_depth <= 0) settings_.max_depth = ch02::DefaultMaxDepth;
}

// BOOK(bidirectional-sample)
void bidirectional_sample(const Scene& scene, const ch03::FixedLightSampler& lights, const BidirectionalSettings& settings,
                          const Vec2& film, SampleStream& samples, ScratchArena& arena, SubpathStorage& storage,
                          const std::function<void(const BidirectionalContribution&)>& record) {
    // A path of max_depth segments has max_depth + 1 vertices: all of them on the camera side
    // for s = 0, all but the pinhole on the light side for t = 1.
    const int max_depth = settings.max_depth;
    storage.camera.resize(static_cast<std::size_t>(max_depth) + 1);
    storage.light.resize(static_cast<std::size_t>(max_depth));
    const int camera_count =
        camera_subpath(scene, scene.camera->generate_ray(film), samples, arena, max_depth + 1, storage.camera.data());
    const int light_count = light_subpath(scene, lights, samples, arena, max_depth, storage.light.data());

    // Every strategy (s, t) of every length: t >= 1 (a pinhole cannot be hit), s + t >= 2.
    samples.start_stream(ConnectionStream);
    for (int t = 1; t <= camera_count; ++t)
        for (int s = 0; s <= light_count; ++s) {
            const int segments = s + t - 1;
            if (segments < 1 || segments > max_depth) continue;
            const StrategyContribution c = connect_strategy(scene, lights, settings.heuristic, storage.light.data(), s,
                                                            storage.camera.data(), t, samples);
            if (is_black(c.unweighted)) continue;
            record({c.at_raster ? c.raster_position : film, c.unweighted * c.weight, c.unweighted, s, t});
        }
}
// END BOOK

// BOOK(bdpt-render)
RenderResult BidirectionalPathTracer::render(const Scene& scene, const RenderSettings& settings, Progress& progress) const {
    const ch03::FixedLightSampler lights(scene.lights, ch03::LightSelection::Power);
    const Camera& pinhole = *scene.camera;
    const StrategyLayers layers(settings_.max_depth);
    const bool strategy_images = !settings_.strategy_images_folder.empty();

    const LightPathEstimator estimator = [&](std::uint32_t slot, PCG32& random, Sampler* sampler, ScratchArena& arena,
                                             SplatBuffer& splats) {
        thread_local SubpathStorage storage;
        // The render's sampler when it has one (chapter 09), else the slot's own stream.
        IndependentSamples independent(random);
        std::optional<PixelSampleStream> from_sampler;
        if (sampler != nullptr) from_sampler.emplace(*sampler);
        SampleStream& samples = from_sampler ? static_cast<SampleStream&>(*from_sampler) : independent;
        // One sample per pixel and batch: the film position within this slot's pixel.
        const int x = static_cast<int>(slot % static_cast<std::uint32_t>(pinhole.width()));
        const int y = static_cast<int>(slot / static_cast<std::uint32_t>(pinhole.width()));
        const Vec2 film = Vec2(static_cast<float>(x), static_cast<float>(y)) + samples.next_2d();
        bidirectional_sample(scene, lights, settings_, film, samples, arena, storage,
                             [&](const BidirectionalContribution& c) {
                                 if (!is_black(c.weighted)) splats.add_splat(c.raster_position, c.weighted);
                                 if (!strategy_images) return;
                                 if (!is_black(c.weighted))
                                     splats.add_splat(c.raster_position, c.weighted, layers.weighted_layer(c.s, c.t));
                                 if (layers.has_image(c.s, c.t))
                                     splats.add_splat(c.raster_position, c.unweighted, layers.unweighted_layer(c.s, c.t));
                             });
    };
    std::vector<Image> layer_images;
    RenderResult result = render_light_paths(scene, settings, progress, estimator,
                                             strategy_images ? layers.layer_count() : 0, &layer_images);
    if (strategy_images) {
        result.extra_images = layers.named_images(layer_images);
        result.extra_images_folder = settings_.strategy_images_folder;
    }
    return result;
}
// END BOOK

BidirectionalSettings read_bidirectional_settings(const Parameters& options, int max_depth,
                                                  ch03::MisHeuristic heuristic) {
    BidirectionalSettings s;
    s.max_depth = max_depth;
    s.heuristic = heuristic;
    s.strategy_images_folder = options.get_string("bdpt_strategies", s.strategy_images_folder);
    if (options.has("bdpt_strategies")) {
        if (s.strategy_images_folder.empty()) throw InputError(options.where("bdpt_strategies"), "names no folder");
        check_strategy_images_folder(s.strategy_images_folder, options.where("bdpt_strategies"));
    }
    return s;
}

}  // namespace freezeray::ch04
