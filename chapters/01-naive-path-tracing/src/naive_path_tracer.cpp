// Naive path tracing: the Monte Carlo estimator of the rendering equation with uniform
// hemisphere sampling (Kajiya, "The Rendering Equation", SIGGRAPH 1986; book chapter 01).
#include "freezeray/ch01/naive_path_tracer.hpp"

#include "freezeray/error.hpp"
#include "freezeray/ch01/warps.hpp"

namespace freezeray::ch01 {

// BOOK(naive-direction)
// The direction of the next bounce, uniform over the hemisphere on the side of wo, or over the
// whole sphere when the material transmits light (so that glass is not black: the estimator
// only needs eval, and the sphere covers both lobes). Returns the direction and its pdf.
static std::pair<Vec3, float> sample_naive_direction(const Vec3& wo, std::uint32_t bsdf_flags, const Vec2& u) {
    if (has_flag(bsdf_flags, BSDF_Transmission)) return {sample_uniform_sphere(u), uniform_sphere_pdf()};
    Vec3 wi = sample_uniform_hemisphere(u);
    if (wo.z < 0.0f) wi.z = -wi.z;
    return {wi, uniform_hemisphere_pdf()};
}
// END BOOK

// BOOK(naive-li)
Spectrum NaivePathTracer::li(const Ray& camera_ray, const Scene& scene, Sampler& sampler, ScratchArena& arena) const {
    Spectrum radiance(0.0f);
    Spectrum throughput(1.0f);  // the product of f cos / pdf along the path so far
    Ray ray = camera_ray;
    for (int segments = 1; segments <= max_depth_; ++segments) {
        const std::optional<Hit> hit = scene.intersect(ray);
        if (!hit) {  // the ray leaves the scene: the sky (black unless the scene has an environment)
            radiance += throughput * scene.environment_radiance(ray);
            break;
        }
        const Material& material = scene.material(*hit);
        const Vec3 wo_world = -ray.direction;
        sampler.start_vertex(segments);  // this vertex's random numbers (chapter 09)

        // Light is only found when the path happens to hit an emitter.
        radiance += throughput * emitted_radiance(material, *hit, wo_world);
        if (segments == max_depth_) break;

        // Continue the path in a uniformly chosen direction, weighted by f cos / pdf.
        const BSDF& bsdf = *material.bsdf(*hit, arena);
        const Frame frame(hit->shading_normal);
        const Vec3 wo = frame.to_local(wo_world);
        const auto [wi, pdf] = sample_naive_direction(wo, bsdf.flags(), sampler.get_2d(VertexDimension::BsdfDirection));
        // EXERCISE(ch01/path-throughput): update the throughput for this bounce, as the Monte Carlo estimator of book chapter 01 ("The Monte Carlo estimator") weighs a sampled direction: the BRDF, the cosine term and the sampling density
        throughput *= bsdf.eval(wo, wi) * abs_cos_theta(wi) / pdf;
        // END EXERCISE
        if (is_black(throughput)) break;
        ray = hit->spawn_ray(frame.to_world(wi));
    }
    return radiance;
}
// END BOOK

}  // namespace freezeray::ch01
