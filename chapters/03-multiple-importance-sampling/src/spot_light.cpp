// Spot lights (pbrt-v4, section 12.2.2).
#include "freezeray/ch03/spot_light.hpp"

#include "freezeray/ch03/point_light.hpp"
#include "freezeray/error.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch03 {

SpotLight::SpotLight(const Vec3& position, const Vec3& axis, const Spectrum& intensity, float cos_cone,
                     float cos_falloff_start)
    : position_(position), frame_(glm::normalize(axis)), intensity_(intensity), cos_cone_(cos_cone),
      cos_falloff_start_(cos_falloff_start) {}

float SpotLight::falloff(float cos_theta) const {
    if (cos_theta >= cos_falloff_start_) return 1.0f;
    if (cos_theta <= cos_cone_) return 0.0f;
    // Smoothstep between the cone's edge and the start of the falloff.
    const float t = (cos_theta - cos_cone_) / (cos_falloff_start_ - cos_cone_);
    return t * t * (3.0f - 2.0f * t);
}

std::optional<LightSample> SpotLight::sample_li(const Vec3& reference, const Vec2&) const {
    const Vec3 to_light = position_ - reference;
    const float distance_squared = glm::dot(to_light, to_light);
    const std::optional<Spectrum> arriving = inverse_square_falloff(intensity_, distance_squared);
    if (!arriving) return std::nullopt;
    const Vec3 wi = to_light / std::sqrt(distance_squared);
    const float fraction = falloff(glm::dot(-wi, frame_.n));
    if (fraction <= 0.0f) return std::nullopt;  // outside the cone
    return LightSample{*arriving * fraction, wi, 1.0f, position_, false};
}

std::optional<LightEmissionSample> SpotLight::sample_le(const Vec2&, const Vec2& u_direction) const {
    // Directions uniform over the cone's solid angle 2 pi (1 - cos_cone).
    const float cos_theta = 1.0f - u_direction.x * (1.0f - cos_cone_);
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    const Vec3 local = spherical_direction(sin_theta, cos_theta, 2.0f * Pi * u_direction.y);
    const float pdf_direction = 1.0f / (2.0f * Pi * (1.0f - cos_cone_));
    return LightEmissionSample{Ray{position_, frame_.to_world(local)}, Vec3(0.0f), intensity_ * falloff(cos_theta), 1.0f,
                               pdf_direction};
}

EmissionDensity SpotLight::pdf_le(const Ray& ray, const Vec3&) const {
    const float cos_theta = glm::dot(frame_.n, ray.direction);
    return {0.0f, cos_theta >= cos_cone_ ? 1.0f / (2.0f * Pi * (1.0f - cos_cone_)) : 0.0f};
}

Spectrum SpotLight::power() const {
    // The integral of I falloff(cos theta) over the sphere: full intensity up to the falloff start,
    // and the smoothstep averages 1/2 over the falloff band (pbrt-v4, SpotLight::Phi).
    return intensity_ * 2.0f * Pi * ((1.0f - cos_falloff_start_) + (cos_falloff_start_ - cos_cone_) / 2.0f);
}

std::unique_ptr<Light> make_spot_light(const Parameters& p) {
    const Vec3 position = p.require_vec3("position");
    Vec3 axis;
    if (p.has("look_at")) {
        if (p.has("direction")) throw InputError(p.where("direction"), "give either \"look_at\" or \"direction\", not both");
        axis = p.require_vec3("look_at") - position;
        if (!(glm::length(axis) > 0.0f)) throw InputError(p.where("look_at"), "equals the light's position");
    } else {
        axis = p.require_vec3("direction");
        if (!(glm::length(axis) > 0.0f)) throw InputError(p.where("direction"), "must not be zero");
    }
    const Spectrum intensity = p.get_spectrum("intensity", Spectrum(1.0f));
    for (int c = 0; c < 3; ++c) p.check_range("intensity", intensity[c], 0.0f, 1e30f);
    const float cone = p.check_range("cone_angle_degrees", p.get_float("cone_angle_degrees", 30.0f), 0.01f, 180.0f);
    const float start =
        p.check_range("falloff_start_degrees", p.get_float("falloff_start_degrees", cone * 0.75f), 0.0f, cone);
    return std::make_unique<SpotLight>(position, axis, intensity, std::cos(glm::radians(cone)),
                                       std::cos(glm::radians(start)));
}

}  // namespace freezeray::ch03
