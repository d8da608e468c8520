// A point light: intensity I (W/sr) from one point in every direction. It cannot be hit by a
// ray, so only light sampling finds it; the radiance it sends to a point at distance r is a
// Dirac delta in direction whose integral is I / r^2 (pbrt-v3, section 12.2).
#pragma once

#include "freezeray/light.hpp"
#include "freezeray/parameters.hpp"

#include <memory>

namespace freezeray::ch03 {

class PointLight final : public Light {
public:
    PointLight(const Vec3& position, const Spectrum& intensity) : position_(position), intensity_(intensity) {}

    LightType type() const override { return LightType::DeltaPosition; }
    std::optional<LightSample> sample_li(const Vec3& reference, const Vec2& u) const override;
    float pdf_li(const Vec3&, const Vec3&) const override { return 0.0f; }
    std::optional<LightEmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction) const override;
    EmissionDensity pdf_le(const Ray& ray, const Vec3& normal) const override;
    Spectrum power() const override { return 4.0f * Pi * intensity_; }

    const Vec3& position() const { return position_; }
    const Spectrum& intensity() const { return intensity_; }

private:
    Vec3 position_;
    Spectrum intensity_;
};

// {"type": "point", "position": [x, y, z], "intensity": [r, g, b]}
std::unique_ptr<Light> make_point_light(const Parameters& p);

// The radiance-like quantity I / r^2 a delta-position light delivers at squared distance r^2, or
// nothing when the reference point is at the light itself (no direction is defined there) or so
// close that I / r^2 overflows.
std::optional<Spectrum> inverse_square_falloff(const Spectrum& intensity, float distance_squared);

}  // namespace freezeray::ch03
