// Generating primary, diffuse and shadow ray batches from a camera.
#include "ray_batch_generator.hpp"

#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/random.hpp"

namespace freezeray::benchmark {

namespace {

// The fixed offset of the shared batches: a fraction of the scene's size, rather than the
// renderer's error-bound offset (offset_ray_origin), so that any ray tracer reading the batch
// starts its rays at exactly the same points.
constexpr float SecondaryOffsetFraction = 1e-4f;

// The shadow ray's target: a uniform point in the bounds, drawn again in the (measure-zero)
// case where it falls on the origin and gives no direction.
Ray shadow_ray(const Vec3& origin, const Bounds3& bounds, PCG32& random) {
    for (;;) {
        const Vec3 u(random.next_float(), random.next_float(), random.next_float());
        const Vec3 target = bounds.min + u * bounds.diagonal();
        const Vec3 to_target = target - origin;
        const float distance = glm::length(to_target);
        if (distance > 0.0f) return Ray{origin, to_target / distance, distance};
    }
}

}  // namespace

CameraDescription shared_batches_camera() {
    CameraDescription camera;
    camera.position = Vec3(1150.0f, 180.0f, -40.0f);
    camera.look_at = Vec3(0.0f, 300.0f, -40.0f);
    camera.up = Vec3(0.0f, 1.0f, 0.0f);
    camera.fov_vertical_degrees = 75.0f;
    camera.width = 512;
    camera.height = 512;
    return camera;
}

Vec3 facing_normal(const Hit& hit, const Vec3& incoming_direction) {
    return glm::dot(hit.geometric_normal, incoming_direction) < 0.0f ? hit.geometric_normal : -hit.geometric_normal;
}

Vec3 secondary_ray_origin(const Hit& hit, const Vec3& incoming_direction, const Bounds3& bounds) {
    return hit.position +
           (SecondaryOffsetFraction * glm::length(bounds.diagonal())) * facing_normal(hit, incoming_direction);
}

RayBatches generate_ray_batches(const Accelerator& accelerator, const Bounds3& bounds,
                                const RayGenerationSettings& settings) {
    const PinholeCamera camera(settings.camera);
    const std::size_t pixel_count = static_cast<std::size_t>(camera.width()) * static_cast<std::size_t>(camera.height());
    RayBatches batches;
    std::vector<Ray>& primary = batches.of(RayKind::Primary);
    std::vector<Ray>& diffuse = batches.of(RayKind::Diffuse);
    std::vector<Ray>& shadow = batches.of(RayKind::Shadow);

    // Pixels are traced in scanline order until every batch has `limit` rays (diffuse and
    // shadow rays need more pixels than that, as some primary rays miss).
    for (std::size_t pixel = 0; pixel < pixel_count; ++pixel) {
        if (primary.size() >= settings.limit && diffuse.size() >= settings.limit) break;
        const int x = static_cast<int>(pixel % static_cast<std::size_t>(camera.width()));
        const int y = static_cast<int>(pixel / static_cast<std::size_t>(camera.width()));
        const Ray ray = camera.generate_ray(Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
        if (primary.size() < settings.limit) primary.push_back(ray);

        const std::optional<Hit> hit = accelerator.intersect(ray);
        if (!hit || diffuse.size() >= settings.limit) continue;
        PCG32 random = make_chain_stream(settings.seed, pixel);
        const Vec3 origin = secondary_ray_origin(*hit, ray.direction, bounds);
        const Frame frame(facing_normal(*hit, ray.direction));
        const Vec2 u(random.next_float(), random.next_float());
        const Vec3 direction = glm::normalize(frame.to_world(ch02::sample_cosine_hemisphere(u)));
        diffuse.push_back(Ray{origin, direction});
        shadow.push_back(shadow_ray(origin, bounds, random));
    }
    return batches;
}

}  // namespace freezeray::benchmark
