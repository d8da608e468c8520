// Path tracing with BSDF importance sampling: every bounce direction is drawn from the BSDF's
// own sampling routine, so f |cos| / pdf stays close to constant and delta lobes (mirrors,
// glass) are followed exactly (book chapter 02).
#include "freezeray/ch02/path_tracer.hpp"

#include <algorithm>

namespace freezeray::ch02 {

// BOOK(russian-roulette)
float russian_roulette(Spectrum& weight, float u) {
    // EXERCISE(ch02/russian-roulette): decide whether the path goes on and reweight a survivor, by the rule of book chapter 02, "`pt-is`", as russian_roulette's comment in path_tracer.hpp states it
    const float q = std::min(0.95f, max_component(weight));
    if (u >= q) return 0.0f;
    weight /= q;
    return q;
    // END EXERCISE
}
// END BOOK

// BOOK(pt-is-li)
Spectrum ImportanceSampledPathTracer::li(const Ray& camera_ray, const Scene& scene, Sampler& sampler,
                                         ScratchArena& arena) const {
    Spectrum radiance(0.0f);
    Spectrum throughput(1.0f);
    Ray ray = camera_ray;
    for (int segments = 1; segments <= max_depth_; ++segments) {
        const std::optional<Hit> hit = scene.intersect(ray);
        if (!hit) {
            radiance += throughput * scene.environment_radiance(ray);
            break;
        }
        const Material& material = scene.material(*hit);
        const Vec3 wo_world = -ray.direction;
        sampler.start_vertex(segments);  // this vertex's random numbers (chapter 09)
        radiance += throughput * emitted_radiance(material, *hit, wo_world);
        if (segments == max_depth_) break;

        const BSDF& bsdf = *material.bsdf(*hit, arena);
        const Frame frame = shading_frame(*hit, bsdf, wo_world);  // two-sided unless it transmits
        const Vec2 u = sampler.get_2d(VertexDimension::BsdfDirection);
        const std::optional<BSDFSample> sample =
            bsdf.sample(frame.to_local(wo_world), u, sampler.get_1d(VertexDimension::BsdfLobe));
        if (!sample || sample->pdf <= 0.0f) break;
        throughput *= sample->weight();
        if (is_black(throughput)) break;

        // Russian roulette: stop with probability 1 - q, and divide the survivors by q, so the
        // expected value is unchanged.
        if (segments >= RussianRouletteStart &&
            russian_roulette(throughput, sampler.get_1d(VertexDimension::Roulette)) == 0.0f)
            break;
        ray = hit->spawn_ray(frame.to_world(sample->wi));
    }
    return radiance;
}
// END BOOK

}  // namespace freezeray::ch02
