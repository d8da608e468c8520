// Path tracing with next-event estimation and multiple importance sampling (book chapter 03;
// Veach 1997, section 9.2; pbrt-v3, section 14.5).
#include "freezeray/ch03/light_sampling_path_tracer.hpp"

#include "freezeray/ch02/path_tracer.hpp"

namespace freezeray::ch03 {

namespace {

// The state of the bounce that led to the current vertex, which decides how the emission found
// there is weighted.
struct PreviousBounce {
    bool specular = true;   // a delta lobe (or the camera): light sampling could not have found this emission
    float bsdf_pdf = 0.0f;  // solid-angle density of the sampled direction
    ShadingPoint point;     // where the bounce happened, as the light sampler saw it there
};

}  // namespace

LightSamplingPathTracer::LightSamplingPathTracer(const LightSamplingSettings& settings) : settings_(settings) {
    if (settings_.max_depth <= 0) settings_.max_depth = ch02::DefaultMaxDepth;
}

RenderResult LightSamplingPathTracer::render(const Scene& scene, const RenderSettings& settings, Progress& progress) const {
    // The render's light sampler (`--light-sampler`), else this integrator's own.
    const FixedLightSampler own(scene.lights, settings_.selection);
    const LightSampler& lights = settings.light_sampler && !settings_.selection_fixed ? *settings.light_sampler : own;
    return render_pixels(scene, settings, progress, [&](const Ray& ray, Sampler& sampler, ScratchArena& arena) {
        return li(ray, scene, lights, sampler, arena);
    });
}

// BOOK(sample-one-light)
// The light arriving at `hit` from one light chosen by the light sampler, reflected towards wo:
// f Li |cos theta_i| / (P(light) p(wi)), weighted against BSDF sampling when combining by MIS.
static Spectrum sample_one_light(const Hit& hit, const ShadingPoint& point, const Frame& frame, const Vec3& wo, const BSDF& bsdf,
                                 const Scene& scene, const LightSampler& lights, const LightSamplingSettings& settings,
                                 Sampler& sampler) {
    const float u_select = sampler.get_1d(VertexDimension::LightChoice);
    const Vec2 u_light = sampler.get_2d(VertexDimension::LightPosition);
    const std::optional<LightChoice> choice = lights.sample(point, u_select);
    if (!choice) return Spectrum(0.0f);
    const std::optional<LightSample> sample = choice->light->sample_li(hit.position, u_light);
    if (!sample || sample->pdf <= 0.0f || is_black(sample->radiance)) return Spectrum(0.0f);

    const Vec3 wi = frame.to_local(sample->wi);
    const Spectrum f = bsdf.eval(wo, wi) * abs_cos_theta(wi);
    if (is_black(f)) return Spectrum(0.0f);
    const Ray shadow_ray = sample->infinite ? hit.spawn_ray(sample->wi) : hit.spawn_ray_to(sample->position);
    if (scene.occluded(shadow_ray)) return Spectrum(0.0f);

    const float light_pdf = choice->probability * sample->pdf;
    float weight = 1.0f;
    if (settings.combination == Combination::MultipleImportanceSampling && !is_delta_light(choice->light->type()))
        weight = mis_weight(settings.heuristic, light_pdf, bsdf.pdf(wo, wi));
    return f * sample->radiance * (weight / light_pdf);
}
// END BOOK

// BOOK(emission-weight)
// The weight of emission Le found by following the BSDF sample of `previous` into `light`
// along direction wi: 1 where light sampling could not have produced the same path (the camera
// ray or a delta lobe before it, emission that belongs to no light, a light the light sampler
// never chooses at that point: probability 0), 0 for next-event estimation (light sampling
// counted it), and otherwise the MIS weight of the BSDF sample (previous.bsdf_pdf) against the
// light sample that could have found the same direction: the probability of choosing this light
// at `previous` times the light's solid-angle density of wi there.
static float emission_weight(const PreviousBounce& previous, const Light* light, const Vec3& wi,
                             const LightSampler& lights, const LightSamplingSettings& settings) {
    // EXERCISE(ch03/emission-weight): the weight of emission found by following a BSDF sample, as this function's comment above states it and book chapter 03, "Multiple importance sampling", explains it: counted once in all, whether light sampling could have found the same light or not
    if (previous.specular || light == nullptr) return 1.0f;
    const float probability = lights.probability(previous.point, *light);
    // Never chosen here (its power rounds to zero, or the light sampler knows it sends no light
    // to this point): only BSDF sampling finds it.
    if (probability == 0.0f) return 1.0f;
    if (settings.combination == Combination::NextEventEstimation) return 0.0f;
    const float light_pdf = probability * light->pdf_li(previous.point.position, wi);
    return mis_weight(settings.heuristic, previous.bsdf_pdf, light_pdf);
    // END EXERCISE
}
// END BOOK

// BOOK(pt-mis-li)
Spectrum LightSamplingPathTracer::li(const Ray& camera_ray, const Scene& scene, const LightSampler& lights,
                                     Sampler& sampler, ScratchArena& arena) const {
    Spectrum radiance(0.0f);
    Spectrum throughput(1.0f);
    Ray ray = camera_ray;
    PreviousBounce previous;  // the camera: what it sees directly is never light-sampled
    for (int segments = 1; segments <= settings_.max_depth; ++segments) {
        const std::optional<Hit> hit = scene.intersect(ray);
        if (!hit) {
            if (scene.environment != nullptr)
                radiance += throughput * scene.environment->le(ray.direction) *
                            emission_weight(previous, scene.environment, ray.direction, lights, settings_);
            break;
        }
        const Material& material = scene.material(*hit);
        const Vec3 wo_world = -ray.direction;
        sampler.start_vertex(segments);  // this vertex's random numbers (chapter 09)
        const Spectrum emitted = emitted_radiance(material, *hit, wo_world);
        if (!is_black(emitted))
            radiance += throughput * emitted *
                        emission_weight(previous, scene.area_light(*hit), ray.direction, lights, settings_);
        if (segments == settings_.max_depth) break;

        const BSDF& bsdf = *material.bsdf(*hit, arena);
        const Frame frame = shading_frame(*hit, bsdf, wo_world);  // two-sided unless it transmits
        const Vec3 wo = frame.to_local(wo_world);

        const ShadingPoint point = shading_point(*hit, frame, wo, bsdf);

        // Next-event estimation: a light sample at every vertex with a non-delta lobe.
        if (bsdf.flags() & (BSDF_Diffuse | BSDF_Glossy))
            radiance += throughput * sample_one_light(*hit, point, frame, wo, bsdf, scene, lights, settings_, sampler);

        // Continue the path by sampling the BSDF (chapter 02).
        const Vec2 u = sampler.get_2d(VertexDimension::BsdfDirection);
        const std::optional<BSDFSample> sample = bsdf.sample(wo, u, sampler.get_1d(VertexDimension::BsdfLobe));
        if (!sample || sample->pdf <= 0.0f) break;
        throughput *= sample->weight();
        if (is_black(throughput)) break;
        previous = {has_flag(sample->flags, BSDF_Specular), sample->pdf, point};

        if (segments >= ch02::RussianRouletteStart &&
            ch02::russian_roulette(throughput, sampler.get_1d(VertexDimension::Roulette)) == 0.0f)
            break;
        ray = hit->spawn_ray(frame.to_world(sample->wi));
    }
    return radiance;
}
// END BOOK

}  // namespace freezeray::ch03
