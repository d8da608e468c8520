// The share of an image that rests on specular-diffuse-specular paths (see sds_probe.hpp).
#include "freezeray/sds_probe.hpp"

#include "freezeray/error.hpp"
#include "freezeray/light_sampler.hpp"
#include "freezeray/material.hpp"
#include "freezeray/parallel.hpp"
#include "freezeray/random.hpp"
#include "freezeray/scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace freezeray {

namespace {

// A surface whose every lobe is a delta: no connection can end on it or pass it.
bool only_specular(const Material& material) {
    const std::uint32_t flags = material.flags();
    return has_flag(flags, BSDF_Specular) && !(flags & (BSDF_Diffuse | BSDF_Glossy));
}

// A light for `point`: chosen by `lights` when there is one, else uniformly.
std::optional<LightChoice> choose_light(const Scene& scene, const LightSampler* lights, const ShadingPoint& point,
                                        float u) {
    if (lights != nullptr) return lights->sample(point, u);
    const auto count = static_cast<std::uint32_t>(scene.lights.size());
    const std::uint32_t index = std::min(count - 1, static_cast<std::uint32_t>(u * static_cast<float>(count)));
    return LightChoice{scene.lights[index].get(), 1.0f / static_cast<float>(count)};
}

// One probe: where its camera ray reaches a diffuse or glossy surface through one specular bounce
// or more, and light arrives there (or would, through specular surfaces), the specularly blocked
// share of that light; else nothing.
std::optional<double> probe(const Scene& scene, const LightSampler* lights, const SdsProbeSettings& settings,
                            PCG32& random, ScratchArena& arena) {
    const PinholeCamera& camera = *scene.camera;
    Ray ray = camera.generate_ray({random.next_float() * static_cast<float>(camera.width()),
                                   random.next_float() * static_cast<float>(camera.height())});
    int specular_bounces = 0;
    for (;;) {
        arena.reset();
        const std::optional<Hit> hit = scene.intersect(ray);
        if (!hit) return std::nullopt;
        const Material& material = scene.material(*hit);
        const BSDF& bsdf = *material.bsdf(*hit, arena);
        const Vec3 wo_world = -ray.direction;
        const Frame frame = shading_frame(*hit, bsdf, wo_world);
        const Vec3 wo = frame.to_local(wo_world);
        if (bsdf.flags() & (BSDF_Diffuse | BSDF_Glossy)) {
            if (specular_bounces == 0) return std::nullopt;  // seen directly: connections reach it from the camera
            const ShadingPoint point = shading_point(*hit, frame, wo, bsdf);
            double blocked = 0.0, arriving = 0.0;
            for (int i = 0; i < settings.light_samples; ++i) {
                const float u_select = random.next_float();
                const Vec2 u_light{random.next_float(), random.next_float()};
                const std::optional<LightChoice> choice = choose_light(scene, lights, point, u_select);
                if (!choice) continue;
                const Light* light = choice->light;
                const float probability = choice->probability;
                const std::optional<LightSample> sample = light->sample_li(hit->position, u_light);
                if (!sample || sample->pdf <= 0.0f || probability <= 0.0f) continue;
                const double contribution = luminance(sample->radiance) *
                                            std::abs(glm::dot(hit->shading_normal, sample->wi)) / (probability * sample->pdf);
                if (!(contribution > 0.0) || !std::isfinite(contribution)) continue;
                const Ray shadow = sample->infinite ? hit->spawn_ray(sample->wi) : hit->spawn_ray_to(sample->position);
                const std::optional<Hit> blocker = scene.intersect(shadow);
                if (!blocker) {
                    arriving += contribution;
                } else if (only_specular(scene.material(*blocker))) {
                    arriving += contribution;
                    blocked += contribution;
                }
            }
            if (arriving > 0.0) return blocked / arriving;
            return std::nullopt;
        }
        // Only delta lobes: follow one, as every path through here must.
        if (++specular_bounces > settings.max_specular_bounces) return std::nullopt;
        const std::optional<BSDFSample> sample =
            bsdf.sample(wo, {random.next_float(), random.next_float()}, random.next_float());
        if (!sample || sample->pdf <= 0.0f) return std::nullopt;
        ray = hit->spawn_ray(frame.to_world(sample->wi));
    }
}

}  // namespace

SdsShare measure_sds_share(const Scene& scene, const LightSampler* lights, const SdsProbeSettings& settings) {
    if (!scene.camera) throw InputError("camera", "the SDS probe follows camera rays: the scene has no camera");
    SdsShare result;
    result.probes = settings.probes;
    if (settings.probes == 0 || scene.lights.empty()) return result;
    const int threads = resolve_thread_count(settings.threads);
    std::vector<ScratchArena> arenas(static_cast<std::size_t>(threads));
    std::vector<std::optional<double>> values(settings.probes);
    parallel_for(settings.probes, threads, [&](std::size_t i, int thread) {
        PCG32 random(settings.seed, i);  // each probe its own stream: the same result on any number of threads
        values[i] = probe(scene, lights, settings, random, arenas[static_cast<std::size_t>(thread)]);
    });
    double sum = 0.0, sum_squares = 0.0;
    std::size_t through = 0;
    for (const std::optional<double>& v : values) {
        if (!v) continue;
        ++through;
        sum += *v;
        sum_squares += *v * *v;
    }
    const auto n = static_cast<double>(settings.probes);
    result.share = sum / n;
    result.lit_through_specular_view = static_cast<double>(through) / n;
    const double variance = n > 1.0 ? std::max(0.0, (sum_squares - sum * sum / n) / (n - 1.0)) : 0.0;
    result.standard_error = std::sqrt(variance / n);
    return result;
}

}  // namespace freezeray
