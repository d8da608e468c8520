// Directional lights (pbrt-v3, section 12.4).
#include "freezeray/ch03/directional_light.hpp"

#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/error.hpp"

#include <cmath>
#include <limits>

namespace freezeray::ch03 {

void bounding_sphere(const Bounds3& bounds, Vec3& center, float& radius) {
    if (bounds.empty()) {
        center = Vec3(0.0f);
        radius = 0.0f;
        return;
    }
    center = 0.5f * (bounds.min + bounds.max);
    radius = glm::length(bounds.max - center);
}

Ray ray_through_bounding_disk(const Vec3& direction, const Vec3& center, float radius, const Vec2& u) {
    const Frame frame(direction);
    const Vec2 disk = ch02::sample_concentric_disk(u) * radius;
    const Vec3 origin = center - radius * direction + disk.x * frame.s + disk.y * frame.t;
    return Ray{origin, direction};
}

std::optional<LightSample> DirectionalLight::sample_li(const Vec3& reference, const Vec2&) const {
    (void)reference;
    return LightSample{irradiance_, -direction_, 1.0f, Vec3(0.0f), true};
}

std::optional<LightEmissionSample> DirectionalLight::sample_le(const Vec2& u_position, const Vec2&) const {
    if (!(scene_radius_ > 0.0f)) return std::nullopt;
    const Ray ray = ray_through_bounding_disk(direction_, scene_center_, scene_radius_, u_position);
    return LightEmissionSample{ray, direction_, irradiance_, 1.0f / (Pi * scene_radius_ * scene_radius_), 1.0f};
}

EmissionDensity DirectionalLight::pdf_le(const Ray&, const Vec3&) const {
    return {1.0f / (Pi * scene_radius_ * scene_radius_), 0.0f};
}

void DirectionalLight::preprocess(const Bounds3& scene_bounds) {
    bounding_sphere(scene_bounds, scene_center_, scene_radius_);
}

std::unique_ptr<Light> make_directional_light(const Parameters& p) {
    const Vec3 direction = p.require_vec3("direction");
    if (!(glm::length(direction) > 0.0f) || !std::isfinite(glm::length(direction)))
        throw InputError(p.where("direction"), "must be a direction (not zero)");
    const Spectrum irradiance = p.get_spectrum("irradiance", Spectrum(1.0f));
    for (int c = 0; c < 3; ++c) p.check_range("irradiance", irradiance[c], 0.0f, 1e30f);
    return std::make_unique<DirectionalLight>(direction, irradiance);
}

}  // namespace freezeray::ch03
