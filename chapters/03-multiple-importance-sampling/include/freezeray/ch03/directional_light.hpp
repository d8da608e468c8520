// A directional light: parallel light of irradiance E (W/m^2, measured perpendicular to the
// light) arriving from one direction, like the sun seen from the earth (pbrt-v3, section 12.4).
#pragma once

#include "freezeray/light.hpp"
#include "freezeray/parameters.hpp"

#include <memory>

namespace freezeray::ch03 {

class DirectionalLight final : public Light {
public:
    // direction: the way the light travels (from the light into the scene).
    DirectionalLight(const Vec3& direction, const Spectrum& irradiance)
        : direction_(glm::normalize(direction)), irradiance_(irradiance) {}

    LightType type() const override { return LightType::DeltaDirection; }
    std::optional<LightSample> sample_li(const Vec3& reference, const Vec2& u) const override;
    float pdf_li(const Vec3&, const Vec3&) const override { return 0.0f; }
    std::optional<LightEmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction) const override;
    EmissionDensity pdf_le(const Ray& ray, const Vec3& normal) const override;
    // The power crossing the scene's bounding disk: E pi r^2.
    Spectrum power() const override { return irradiance_ * Pi * scene_radius_ * scene_radius_; }
    void preprocess(const Bounds3& scene_bounds) override;

private:
    Vec3 direction_;
    Spectrum irradiance_;
    Vec3 scene_center_{0.0f};
    float scene_radius_ = 0.0f;
};

// {"type": "directional", "direction": [x, y, z], "irradiance": [r, g, b]}
std::unique_ptr<Light> make_directional_light(const Parameters& p);

// The bounding sphere of a box (centre and radius), for lights at infinity.
void bounding_sphere(const Bounds3& bounds, Vec3& center, float& radius);

// A ray entering the scene's bounding sphere along `direction` through a uniform point of the
// disk perpendicular to it (for light paths from lights at infinity; pbrt-v3, section 12.4).
// Returns the ray; the point's area density is 1 / (pi radius^2).
Ray ray_through_bounding_disk(const Vec3& direction, const Vec3& center, float radius, const Vec2& u);

}  // namespace freezeray::ch03
