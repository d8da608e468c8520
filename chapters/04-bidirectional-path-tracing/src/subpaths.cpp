// Camera and light subpaths (book chapter 04; Veach 1997, section 10.2; pbrt-v3, section 16.3.2).
#include "freezeray/ch04/subpaths.hpp"

#include "freezeray/ch02/path_tracer.hpp"
#include "freezeray/ch04/light_tracer.hpp"

#include <cmath>

namespace freezeray::ch04 {

namespace {

// BOOK(random-walk)
// Extends a subpath whose last vertex is path[-1] along `ray`, sampled from it with solid-angle
// density pdf_direction; writes at most max_vertices more vertices and returns how many.
// `beta` is the subpath's throughput, `scattering` the part of it that Russian roulette looks
// at (for a light subpath the emitted power is not part of it: it is in watts, not a fraction).
int random_walk(const Scene& scene, Ray ray, SampleStream& samples, ScratchArena& arena, Spectrum beta, Spectrum scattering,
                float pdf_direction, int max_vertices, Transport transport, PathVertex* path) {
    if (max_vertices <= 0) return 0;
    int count = 0;
    float pdf_forward = pdf_direction;  // density of the direction that led to the next vertex
    while (true) {
        PathVertex& previous = path[count - 1];
        PathVertex& vertex = path[count];
        const std::optional<Hit> hit = scene.intersect(ray);
        if (!hit) {
            // A camera subpath that escapes ends on the environment: the s = 0 strategy finds
            // its light there. Its "position" is one unit along the ray: only the direction counts.
            if (transport == Transport::Radiance && scene.environment != nullptr) {
                vertex = PathVertex{};
                vertex.type = VertexType::Light;
                vertex.transport = transport;
                vertex.beta = beta;
                vertex.position = previous.position + ray.direction;
                vertex.light = scene.environment;
                vertex.infinite = true;
                vertex.pdf_fwd = pdf_forward;  // solid angle, the measure of a direction
                ++count;
            }
            break;
        }
        const BSDF& bsdf = *scene.material(*hit).bsdf(*hit, arena);
        vertex = PathVertex{};
        vertex.type = VertexType::Surface;
        vertex.transport = transport;
        vertex.beta = beta;
        vertex.position = hit->position;
        vertex.geometric_normal = hit->geometric_normal;
        vertex.hit = *hit;
        vertex.bsdf = &bsdf;
        vertex.wo = -ray.direction;
        vertex.frame = shading_frame(*hit, bsdf, vertex.wo);
        vertex.light = scene.area_light(*hit);
        vertex.pdf_fwd = convert_density(pdf_forward, previous, vertex);
        if (++count >= max_vertices) break;

        // Sample the next direction. A light subpath scatters with the adjoint BSDF (as light
        // tracing does: the shading-normal correction and eta^2 on transmission).
        const Vec3 wo = vertex.frame.to_local(vertex.wo);
        const Vec2 u = samples.next_2d();
        const std::optional<BSDFSample> sample = bsdf.sample(wo, u, samples.next_float());
        if (!sample || sample->pdf <= 0.0f) break;
        const Vec3 wi_world = vertex.frame.to_world(sample->wi);
        Spectrum weight = sample->weight();
        if (transport == Transport::Importance)
            weight *= adjoint_sample_factor(*sample, vertex.wo, wi_world, vertex.frame.n, hit->geometric_normal);
        beta *= weight;
        scattering *= weight;
        if (is_black(beta)) break;

        // The reverse density: the previous vertex as sampled from this one, the other way.
        pdf_forward = sample->pdf;
        float pdf_reverse = bsdf.pdf(sample->wi, wo);
        if (has_flag(sample->flags, BSDF_Specular)) {
            // A delta lobe: densities are not comparable with area densities; strategies that
            // would connect here are impossible, and the MIS weights skip them (mis.cpp).
            vertex.delta = true;
            pdf_forward = pdf_reverse = 0.0f;
        }
        previous.pdf_rev = convert_density(pdf_reverse, vertex, previous);

        // Russian roulette, as chapter 02's path tracer. The MIS densities leave it out: every
        // strategy divides by its own survival probabilities, so the estimate stays unbiased
        // and the weights of a path still sum to one.
        if (count >= ch02::RussianRouletteStart) {
            const float q = ch02::russian_roulette(scattering, samples.next_float());
            if (q == 0.0f) break;
            beta /= q;
        }
        ray = hit->spawn_ray(wi_world);
    }
    return count;
}
// END BOOK

}  // namespace

// BOOK(camera-subpath)
int camera_subpath(const Scene& scene, const Ray& camera_ray, SampleStream& samples, ScratchArena& arena, int max_vertices,
                   PathVertex* path) {
    if (max_vertices <= 0) return 0;
    PathVertex& camera = path[0];
    camera = PathVertex{};
    camera.type = VertexType::Camera;
    camera.beta = Spectrum(1.0f);  // We / pdf = 1 for a pixel's rays: the box filter
    camera.position = camera_ray.origin;
    const float pdf_direction = scene.camera->pdf_direction(camera_ray);
    return 1 + random_walk(scene, camera_ray, samples, arena, Spectrum(1.0f), Spectrum(1.0f), pdf_direction,
                           max_vertices - 1, Transport::Radiance, path + 1);
}
// END BOOK

// BOOK(light-subpath)
int light_subpath(const Scene& scene, const ch03::FixedLightSampler& lights, SampleStream& samples, ScratchArena& arena,
                  int max_vertices, PathVertex* path) {
    if (max_vertices <= 0) return 0;
    samples.start_stream(LightStream);
    const std::optional<ch03::FixedLightSampler::Choice> choice = lights.sample(samples.next_float());
    const Vec2 u_position = samples.next_2d();
    const Vec2 u_direction = samples.next_2d();
    if (!choice || choice->probability <= 0.0f) return 0;
    const std::optional<LightEmissionSample> emission = choice->light->sample_le(u_position, u_direction);
    if (!emission || emission->pdf_position <= 0.0f || emission->pdf_direction <= 0.0f || is_black(emission->radiance))
        return 0;

    const LightType type = choice->light->type();
    PathVertex& light = path[0];
    light = PathVertex{};
    light.type = VertexType::Light;
    light.transport = Transport::Importance;
    light.position = emission->ray.origin;
    light.light = choice->light;
    light.infinite = type == LightType::Infinite || type == LightType::DeltaDirection;
    if (type == LightType::Area) light.geometric_normal = emission->normal;
    // Le / (P(light) p_A): the light vertex's throughput, for s = 1, t = 1 (the light seen directly).
    light.beta = emission->radiance / (choice->probability * emission->pdf_position);
    light.pdf_fwd = choice->probability * emission->pdf_position;

    // Le |cos| / (P(light) p_A p_w) (pbrt-v3, eq. 16.15); the cosine is 1 without a surface.
    const float cos_light = glm::dot(emission->normal, emission->normal) > 0.0f
                                ? std::abs(glm::dot(emission->normal, emission->ray.direction))
                                : 1.0f;
    const Spectrum beta = light.beta * (cos_light / emission->pdf_direction);
    const Vec3& origin = emission->ray.origin;
    const Ray ray{offset_ray_origin(origin, emission_origin_error(origin), emission->normal, emission->ray.direction),
                  emission->ray.direction};
    const int count = 1 + random_walk(scene, ray, samples, arena, beta, Spectrum(1.0f), emission->pdf_direction,
                                      max_vertices - 1, Transport::Importance, path + 1);

    // A light at infinity: its "position" is the direction light comes from, sampled with the
    // solid-angle density pdf_direction; the second vertex's density is the disk's area density
    // projected onto its surface, no distance involved (pbrt-v3, GenerateLightSubpath).
    if (light.infinite) {
        if (count > 1) {
            path[1].pdf_fwd = emission->pdf_position;
            if (path[1].on_surface()) path[1].pdf_fwd *= std::abs(glm::dot(path[1].geometric_normal, emission->ray.direction));
        }
        light.pdf_fwd = type == LightType::DeltaDirection ? 0.0f : choice->probability * emission->pdf_direction;
    }
    return count;
}
// END BOOK

}  // namespace freezeray::ch04
