// Point lights (pbrt-v3, section 12.2).
#include "freezeray/ch03/point_light.hpp"

#include "freezeray/ch01/warps.hpp"

#include <cmath>

namespace freezeray::ch03 {

std::optional<Spectrum> inverse_square_falloff(const Spectrum& intensity, float distance_squared) {
    if (!(distance_squared > 0.0f)) return std::nullopt;
    const Spectrum arriving = intensity / distance_squared;
    if (!std::isfinite(arriving.r) || !std::isfinite(arriving.g) || !std::isfinite(arriving.b)) return std::nullopt;
    return arriving;
}

// BOOK(point-light-sample)
std::optional<LightSample> PointLight::sample_li(const Vec3& reference, const Vec2&) const {
    const Vec3 to_light = position_ - reference;
    const float distance_squared = glm::dot(to_light, to_light);
    const std::optional<Spectrum> arriving = inverse_square_falloff(intensity_, distance_squared);
    if (!arriving) return std::nullopt;
    // pdf 1: the only direction there is, chosen with certainty.
    return LightSample{*arriving, to_light / std::sqrt(distance_squared), 1.0f, position_, false};
}
// END BOOK

std::optional<LightEmissionSample> PointLight::sample_le(const Vec2&, const Vec2& u_direction) const {
    const Vec3 direction = ch01::sample_uniform_sphere(u_direction);
    return LightEmissionSample{Ray{position_, direction}, Vec3(0.0f), intensity_, 1.0f, ch01::uniform_sphere_pdf()};
}

EmissionDensity PointLight::pdf_le(const Ray&, const Vec3&) const { return {0.0f, ch01::uniform_sphere_pdf()}; }

std::unique_ptr<Light> make_point_light(const Parameters& p) {
    const Vec3 position = p.require_vec3("position");
    const Spectrum intensity = p.get_spectrum("intensity", Spectrum(1.0f));
    for (int c = 0; c < 3; ++c) p.check_range("intensity", intensity[c], 0.0f, 1e30f);
    return std::make_unique<PointLight>(position, intensity);
}

}  // namespace freezeray::ch03
