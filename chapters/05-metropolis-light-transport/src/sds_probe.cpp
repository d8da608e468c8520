// The share of an image that rests on specular-diffuse-specular paths (see sds_probe.hpp).
#include "freezeray/ch05/sds_probe.hpp"

#include "freezeray/error.hpp"
#include "freezeray/light_sampler.hpp"
#include "freezeray/material.hpp"
#include "freezeray/parallel.hpp"
#include "freezeray/random.hpp"
#include "freezeray/scene.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace freezeray::ch05 {

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

// Where `ray` ends after the surfaces with delta lobes only, each passed by sampling its BSDF, as
// every path through them must: the first surface with a diffuse or glossy lobe (or, with
// `stop_at_emitters`, the first emitter, whatever its lobes), with the ray that reached it and
// the number of specular bounces before it; no hit when the ray leaves the scene, a sample fails,
// or it bounces more than max_specular_bounces times. The end surface's BSDF is in `arena`.
struct SpecularChainEnd {
    std::optional<Hit> hit;
    Ray ray;  // the ray that found `hit`
    const BSDF* bsdf = nullptr;
    int specular_bounces = 0;
};
SpecularChainEnd follow_specular_chain(const Scene& scene, Ray ray, bool stop_at_emitters, const SdsProbeSettings& settings,
                                       PCG32& random, ScratchArena& arena) {
    for (int bounces = 0;; ++bounces) {
        const std::optional<Hit> hit = scene.intersect(ray);
        if (!hit) return {};
        const Material& material = scene.material(*hit);
        const BSDF& bsdf = *material.bsdf(*hit, arena);
        if ((bsdf.flags() & (BSDF_Diffuse | BSDF_Glossy)) ||
            (stop_at_emitters && !is_black(emitted_radiance(material, *hit, -ray.direction))))
            return {hit, ray, &bsdf, bounces};
        if (bounces == settings.max_specular_bounces) return {};
        const Frame frame = shading_frame(*hit, bsdf, -ray.direction);
        const std::optional<BSDFSample> sample =
            bsdf.sample(frame.to_local(-ray.direction), {random.next_float(), random.next_float()}, random.next_float());
        if (!sample || sample->pdf <= 0.0f) return {};
        ray = hit->spawn_ray(frame.to_world(sample->wi));
    }
}

// Whether a direction sampled from the BSDF at `hit`, followed through one specular bounce or
// more, reaches an emitter: one try of the only strategy that makes an SDS path (a camera path
// hitting the light through a specular surface; an emitter seen directly is light sampling's).
bool camera_strategy_hits(const Scene& scene, const Hit& hit, const BSDF& bsdf, const Frame& frame, const Vec3& wo,
                          const SdsProbeSettings& settings, PCG32& random, ScratchArena& arena) {
    arena.reset();  // its own arena: the surface's BSDF lives in the probe's
    const std::optional<BSDFSample> first = bsdf.sample(wo, {random.next_float(), random.next_float()}, random.next_float());
    if (!first || first->pdf <= 0.0f) return false;
    const SpecularChainEnd end =
        follow_specular_chain(scene, hit.spawn_ray(frame.to_world(first->wi)), true, settings, random, arena);
    return end.hit && end.specular_bounces > 0 &&
           !is_black(emitted_radiance(scene.material(*end.hit), *end.hit, -end.ray.direction));
}

struct ProbeResult {
    std::optional<double> value;  // see probe()
    bool lit_through_specular = false;  // the value is above 0: some light arrives through a specular surface
    std::uint64_t tries = 0, hits = 0;
};

// One probe: where its camera ray reaches a diffuse or glossy surface through one specular bounce
// or more, and light arrives there (or would, through specular surfaces), the specularly blocked
// share of that light; else nothing. Where that share is not 0, the camera strategy's tries.
ProbeResult probe(const Scene& scene, const LightSampler* lights, const SdsProbeSettings& settings,
                  std::uint64_t tries, PCG32& random, ScratchArena& arena, ScratchArena& tries_arena) {
    const Camera& camera = *scene.camera;
    const Ray camera_ray = camera.generate_ray({random.next_float() * static_cast<float>(camera.width()),
                                                random.next_float() * static_cast<float>(camera.height())});
    arena.reset();
    const SpecularChainEnd end = follow_specular_chain(scene, camera_ray, false, settings, random, arena);
    // Seen directly, connections reach it from the camera.
    if (!end.hit || end.specular_bounces == 0) return {};
    const Hit& hit = *end.hit;
    const BSDF& bsdf = *end.bsdf;
    const Vec3 wo_world = -end.ray.direction;
    const Frame frame = shading_frame(hit, bsdf, wo_world);
    const Vec3 wo = frame.to_local(wo_world);
    const ShadingPoint point = shading_point(hit, frame, wo, bsdf);
    double blocked = 0.0, arriving = 0.0;
    for (int i = 0; i < settings.light_samples; ++i) {
        const float u_select = random.next_float();
        const Vec2 u_light{random.next_float(), random.next_float()};
        const std::optional<LightChoice> choice = choose_light(scene, lights, point, u_select);
        if (!choice) continue;
        const Light* light = choice->light;
        const float probability = choice->probability;
        const std::optional<LightSample> sample = light->sample_li(hit.position, u_light);
        if (!sample || sample->pdf <= 0.0f || probability <= 0.0f) continue;
        const double contribution = luminance(sample->radiance) *
                                    std::abs(glm::dot(hit.shading_normal, sample->wi)) / (probability * sample->pdf);
        if (!(contribution > 0.0) || !std::isfinite(contribution)) continue;
        const Ray shadow = sample->infinite ? hit.spawn_ray(sample->wi) : hit.spawn_ray_to(sample->position);
        const std::optional<Hit> blocker = scene.intersect(shadow);
        if (!blocker) {
            arriving += contribution;
        } else if (only_specular(scene.material(*blocker))) {
            arriving += contribution;
            blocked += contribution;
        }
    }
    if (!(arriving > 0.0)) return {};
    ProbeResult result{blocked / arriving, blocked > 0.0};
    if (result.lit_through_specular)
        for (; result.tries < tries; ++result.tries)
            result.hits += camera_strategy_hits(scene, hit, bsdf, frame, wo, settings, random, tries_arena) ? 1 : 0;
    return result;
}

}  // namespace

SdsShare measure_sds_share(const Scene& scene, const LightSampler* lights, const SdsProbeSettings& settings) {
    if (!scene.camera) throw InputError("camera", "the SDS probe follows camera rays: the scene has no camera");
    SdsShare result;
    result.probes = settings.probes;
    if (settings.probes == 0 || scene.lights.empty()) return result;
    const int threads = resolve_thread_count(settings.threads);
    std::vector<ScratchArena> arenas(static_cast<std::size_t>(threads)), tries_arenas(static_cast<std::size_t>(threads));
    std::vector<ProbeResult> values(settings.probes);
    parallel_for(settings.probes, threads, [&](std::size_t i, int thread) {
        PCG32 random(settings.seed, i);  // each probe its own stream: the same result on any number of threads
        values[i] = probe(scene, lights, settings, 0, random, arenas[static_cast<std::size_t>(thread)],
                          tries_arenas[static_cast<std::size_t>(thread)]);
    });
    // The camera strategy's tries, spread evenly over the surfaces lit through a specular one:
    // each such probe runs again from its own stream (the same camera ray, the same surface).
    std::vector<std::size_t> lit;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (values[i].lit_through_specular) lit.push_back(i);
    if (settings.camera_strategy_tries > 0 && !lit.empty()) {
        const std::uint64_t tries = (settings.camera_strategy_tries + lit.size() - 1) / lit.size();
        parallel_for(lit.size(), threads, [&](std::size_t k, int thread) {
            PCG32 random(settings.seed, lit[k]);
            values[lit[k]] = probe(scene, lights, settings, tries, random, arenas[static_cast<std::size_t>(thread)],
                                   tries_arenas[static_cast<std::size_t>(thread)]);
        });
    }
    double sum = 0.0, sum_squares = 0.0;
    std::size_t through = 0;
    for (const ProbeResult& r : values) {
        result.camera_strategy_tries += r.tries;
        result.camera_strategy_hits += r.hits;
        if (!r.value) continue;
        ++through;
        sum += *r.value;
        sum_squares += *r.value * *r.value;
    }
    const auto n = static_cast<double>(settings.probes);
    result.share = sum / n;
    result.lit_through_specular_view = static_cast<double>(through) / n;
    const double variance = n > 1.0 ? std::max(0.0, (sum_squares - sum * sum / n) / (n - 1.0)) : 0.0;
    result.standard_error = std::sqrt(variance / n);
    return result;
}

CameraStrategyChance camera_strategy_chance(const SdsShare& sds) {
    CameraStrategyChance chance;
    if (sds.camera_strategy_tries == 0) return chance;
    const auto tries = static_cast<double>(sds.camera_strategy_tries);
    const std::uint64_t hits = sds.camera_strategy_hits;
    // 95 % one-sided upper limits of a Poisson mean after 0..9 events, and beyond them the
    // approximation n + S sqrt(n + 1) + (S^2 + 2) / 3 with S = 1.645 (Gehrels, "Confidence Limits
    // for Small Numbers of Events in Astrophysical Data", 1986, table 1 and equation 9).
    constexpr double PoissonUpper[] = {3.000, 4.744, 6.296, 7.754, 9.154, 10.51, 11.84, 13.15, 14.43, 15.71};
    const auto n = static_cast<double>(hits);
    const double upper_hits = hits < 10 ? PoissonUpper[hits] : n + 1.645 * std::sqrt(n + 1.0) + (1.645 * 1.645 + 2.0) / 3.0;
    chance.p = n / tries;
    chance.p_upper = std::min(1.0, upper_hits / tries);
    chance.tail_per_sample = hits > 0 ? sds.share / chance.p : std::numeric_limits<double>::infinity();
    chance.tail_lower = sds.share / chance.p_upper;
    return chance;
}

std::optional<std::string> chain_advice(double sds_share) {
    if (sds_share <= SdsShareLimit) return std::nullopt;
    return "much of the image is lit through a specular surface and seen through one: only a camera path that hits "
           "the light makes those paths, and a Markov chain explores them once found";
}

std::optional<std::string> advise_chain(const Scene& scene, const AdviceRequest& request) {
    // The probe (a fraction of a second) only where it can find something: a scene with specular
    // surfaces, a camera and lights.
    if (!scene.effects.specular || !scene.camera || scene.lights.empty()) return std::nullopt;
    SdsProbeSettings probe;
    if (request.detailed) probe.camera_strategy_tries = 1u << 20;
    const SdsShare sds = measure_sds_share(scene, request.lights, probe);
    if (request.notes != nullptr) {
        std::ostringstream line;
        line << std::setprecision(3) << "specular-diffuse-specular: " << sds.share
             << " of the image lit through a specular surface and seen through one (of " << sds.lit_through_specular_view
             << " seen through one; standard error " << sds.standard_error << ", " << sds.probes
             << " camera rays); auto trusts only Markov chains above " << SdsShareLimit;
        request.notes->push_back(line.str());
        if (sds.camera_strategy_tries > 0) {
            // How heavy the tail is: the one strategy's chance p there, and share / p.
            const CameraStrategyChance chance = camera_strategy_chance(sds);
            std::ostringstream tail;
            tail << std::setprecision(3) << "  from there, a camera path reaches a light in " << sds.camera_strategy_hits
                 << " of " << sds.camera_strategy_tries << " tries (p " << chance.p << ", 95 % upper bound "
                 << chance.p_upper << "): these paths add ";
            if (sds.camera_strategy_hits > 0)
                tail << "about " << chance.tail_per_sample << " (at least " << chance.tail_lower << ")";
            else
                tail << "more than " << chance.tail_lower;
            tail << " to the expected relMSE at 1 sample per pixel";
            request.notes->push_back(tail.str());
        }
    }
    return chain_advice(sds.share);
}

}  // namespace freezeray::ch05
