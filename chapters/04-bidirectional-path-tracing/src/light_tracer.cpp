// Light tracing: the t = 1 strategies of bidirectional path tracing (book chapter 04; Veach 1997,
// section 10.2; pbrt-v3, sections 16.1 and 16.3).
#include "freezeray/ch04/light_tracer.hpp"

#include "freezeray/ch02/path_tracer.hpp"

#include <cmath>

namespace freezeray::ch04 {

// BOOK(shading-normal-correction)
float shading_normal_correction(const Vec3& wo, const Vec3& wi, const Vec3& shading_normal, const Vec3& geometric_normal) {
    // With shading normals the BSDF is not symmetric: radiance sees |wi.ns| where the true
    // projected area is |wi.ng|. A particle carrying importance's adjoint must exchange the
    // roles of wo and wi (Veach 1997, eq. 5.19).
    const float denominator = std::abs(glm::dot(wo, geometric_normal)) * std::abs(glm::dot(wi, shading_normal));
    if (denominator == 0.0f) return 0.0f;
    return std::abs(glm::dot(wo, shading_normal)) * std::abs(glm::dot(wi, geometric_normal)) / denominator;
}
// END BOOK

float adjoint_sample_factor(const BSDFSample& sample, const Vec3& wo, const Vec3& wi, const Vec3& shading_normal,
                            const Vec3& geometric_normal) {
    float factor = shading_normal_correction(wo, wi, shading_normal, geometric_normal);
    if (has_flag(sample.flags, BSDF_Transmission)) factor *= sample.eta * sample.eta;
    return factor;
}

// BOOK(connect-to-camera)
std::optional<CameraConnection> connect_to_camera(const Scene& scene, const Hit& hit, const BSDF& bsdf, const Frame& frame,
                                                  const Vec3& wo_world, const Spectrum& beta) {
    // The pinhole draws no number (a lens would: chapter 16).
    const std::optional<CameraImportanceSample> camera = scene.camera->sample_wi(hit.position, Vec2(0.5f));
    if (!camera || camera->pdf <= 0.0f || camera->importance <= 0.0f) return std::nullopt;
    // The light arrives from wo_world and leaves towards the camera: in the radiance convention
    // of chapter 02's BSDFs that is f(wo = towards the camera, wi = towards the light). That is
    // the path's own BSDF factor, so no eta^2 is needed here even for refraction: the adjoint
    // BSDF f*(a, b) = f(b, a) is what a light path uses (Veach 1997, section 5.2), and only a
    // BSDF *sampled* from the light's side, f(a, b), needs turning into f(b, a) (the eta^2 of
    // adjoint_sample_factor).
    const Vec3 to_camera = frame.to_local(camera->wi);
    const Spectrum f = bsdf.eval(to_camera, frame.to_local(wo_world));
    if (is_black(f)) return std::nullopt;
    if (scene.occluded(hit.spawn_ray_to(camera->position))) return std::nullopt;
    const float correction = shading_normal_correction(wo_world, camera->wi, frame.n, hit.geometric_normal);
    // EXERCISE(ch04/camera-connection): the contribution of connecting a light subpath vertex to the camera, and where on the film it lands, book chapter 04, "Light tracing" (the camera's importance, the cosine at the vertex, the shading-normal correction, the densities)
    // beta f |cos theta| We / pdf: pdf = distance^2 / cos(theta_camera) turns the pinhole's
    // importance into the importance arriving here (pbrt-v3, section 16.3.1, eq. 16.17).
    const Spectrum value = beta * f * (abs_cos_theta(to_camera) * correction * camera->importance / camera->pdf);
    return CameraConnection{camera->raster_position, value};
    // END EXERCISE
}
// END BOOK

Vec3 emission_origin_error(const Vec3& point) { return glm::abs(point) * 0x1p-18f; }

// BOOK(connect-light-to-camera)
std::optional<CameraConnection> connect_light_to_camera(const Scene& scene, const LightEmissionSample& emission,
                                                        float light_probability) {
    const Vec3& point = emission.ray.origin;
    const std::optional<CameraImportanceSample> camera = scene.camera->sample_wi(point, Vec2(0.5f));
    if (!camera || camera->pdf <= 0.0f || camera->importance <= 0.0f) return std::nullopt;
    // An area light is a one-sided Lambertian emitter: the same radiance towards the camera as
    // along the sampled ray, if the camera is in front of it.
    const float cos_light = glm::dot(emission.normal, camera->wi);
    if (cos_light <= 0.0f) return std::nullopt;
    const Vec3 origin = offset_ray_origin(point, emission_origin_error(point), emission.normal, camera->wi);
    const float distance = glm::length(camera->position - origin);
    if (scene.occluded(Ray{origin, camera->wi, distance * (1.0f - 1e-4f)})) return std::nullopt;
    // Le cos(theta_light) We / (P(light) p_A(point) p(camera)): the emission of the chosen point
    // carried to the pinhole (the s = 1, t = 1 strategy; Veach 1997, section 10.2).
    const Spectrum value = emission.radiance * (cos_light * camera->importance /
                                                (light_probability * emission.pdf_position * camera->pdf));
    return CameraConnection{camera->raster_position, value};
}
// END BOOK

LightTracer::LightTracer(const LightTracingSettings& settings) : settings_(settings) {
    if (settings_.max_depth <= 0) settings_.max_depth = ch02::DefaultMaxDepth;
}

RenderResult LightTracer::render(const Scene& scene, const RenderSettings& settings, Progress& progress) const {
    const ch03::FixedLightSampler lights(scene.lights, ch03::LightSelection::Power);
    return render_light_paths(scene, settings, progress,
                              [&](std::uint32_t, PCG32& random, Sampler*, ScratchArena& arena, SplatBuffer& splats) {
                                  trace_light_path(scene, lights, random, arena, splats);
                              });
}

// BOOK(trace-light-path)
void LightTracer::trace_light_path(const Scene& scene, const ch03::FixedLightSampler& lights, PCG32& random,
                                   ScratchArena& arena, SplatBuffer& splats) const {
    // Choose a light by power and a ray leaving it (chapter 03's sample_le).
    const std::optional<ch03::FixedLightSampler::Choice> choice = lights.sample(random.next_float());
    if (!choice || choice->probability <= 0.0f) return;
    const Vec2 u_position(random.next_float(), random.next_float());
    const Vec2 u_direction(random.next_float(), random.next_float());
    const std::optional<LightEmissionSample> emission = choice->light->sample_le(u_position, u_direction);
    if (!emission || emission->pdf_position <= 0.0f || emission->pdf_direction <= 0.0f || is_black(emission->radiance))
        return;

    // s = 1, t = 1: an emitter seen directly. Only area lights: a pinhole sees a point light
    // with probability zero in every camera-path integrator of the course, and directional and
    // environment lights reach it only along one direction each (see the chapter's README).
    if (choice->light->type() == LightType::Area && settings_.max_depth >= 1)
        if (const auto connection = connect_light_to_camera(scene, *emission, choice->probability))
            splats.add_splat(connection->raster_position, connection->value);

    // The throughput of the path so far: Le |cos| / (P(light) p_A p_w) (pbrt-v3, eq. 16.15), the
    // cosine 1 for point lights (no surface: zero normal).
    const float cos_light = glm::dot(emission->normal, emission->normal) > 0.0f
                                ? std::abs(glm::dot(emission->normal, emission->ray.direction))
                                : 1.0f;
    const Spectrum emitted = emission->radiance * (cos_light / (choice->probability * emission->pdf_position *
                                                                emission->pdf_direction));
    Spectrum scattering(1.0f);  // the product of BSDF weights: what Russian roulette looks at
    const Vec3& origin = emission->ray.origin;
    Ray ray{offset_ray_origin(origin, emission_origin_error(origin), emission->normal, emission->ray.direction),
            emission->ray.direction};
    // `segments` counts the light path's segments; a connection adds one more (to the camera).
    for (int segments = 1; segments + 1 <= settings_.max_depth; ++segments) {
        const std::optional<Hit> hit = scene.intersect(ray);
        if (!hit) break;
        const BSDF& bsdf = *scene.material(*hit).bsdf(*hit, arena);
        const Vec3 wo_world = -ray.direction;  // back towards the light
        // Two-sided reflectors face the arriving light (chapter 02 turns them to the viewer).
        const Frame frame = shading_frame(*hit, bsdf, wo_world);

        // t = 1: connect this vertex to the camera (a delta lobe cannot be connected).
        if (bsdf.flags() & (BSDF_Diffuse | BSDF_Glossy))
            if (const auto connection = connect_to_camera(scene, *hit, bsdf, frame, wo_world, emitted * scattering))
                splats.add_splat(connection->raster_position, connection->value);
        if (segments + 2 > settings_.max_depth) break;

        // Continue by sampling the BSDF from the light's side, weighted as the adjoint BSDF.
        const Vec2 u(random.next_float(), random.next_float());
        const std::optional<BSDFSample> sample = bsdf.sample(frame.to_local(wo_world), u, random.next_float());
        if (!sample || sample->pdf <= 0.0f) break;
        const Vec3 wi_world = frame.to_world(sample->wi);
        scattering *= sample->weight() * adjoint_sample_factor(*sample, wo_world, wi_world, frame.n, hit->geometric_normal);
        if (is_black(scattering)) break;

        // Russian roulette on the scattering alone: the emitted part of the throughput is in
        // watts and says nothing about how much of it the path still carries.
        if (segments >= ch02::RussianRouletteStart && ch02::russian_roulette(scattering, random.next_float()) == 0.0f)
            break;
        ray = hit->spawn_ray(wi_world);
    }
}
// END BOOK

}  // namespace freezeray::ch04
