// A spot light: a point light whose intensity is I inside a cone around its axis, falling off
// smoothly to zero between the falloff-start angle and the cone's edge (pbrt-v4, section 12.2.2).
#pragma once

#include "freezeray/light.hpp"
#include "freezeray/parameters.hpp"

#include <memory>

namespace freezeray::ch03 {

class SpotLight final : public Light {
public:
    // cos_cone: cosine of the cone's half-angle; cos_falloff_start: of the angle where the falloff
    // begins (cos_falloff_start >= cos_cone).
    SpotLight(const Vec3& position, const Vec3& axis, const Spectrum& intensity, float cos_cone, float cos_falloff_start);

    LightType type() const override { return LightType::DeltaPosition; }
    std::optional<LightSample> sample_li(const Vec3& reference, const Vec2& u) const override;
    float pdf_li(const Vec3&, const Vec3&) const override { return 0.0f; }
    std::optional<LightEmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction) const override;
    EmissionDensity pdf_le(const Ray& ray, const Vec3& normal) const override;
    Spectrum power() const override;

    // The fraction of I sent in a direction whose angle to the axis has cosine cos_theta.
    float falloff(float cos_theta) const;

    const Vec3& position() const { return position_; }
    const Vec3& axis() const { return frame_.n; }
    const Spectrum& intensity() const { return intensity_; }
    float cos_cone() const { return cos_cone_; }
    float cos_falloff_start() const { return cos_falloff_start_; }

private:
    Vec3 position_;
    Frame frame_;  // +z along the axis
    Spectrum intensity_;
    float cos_cone_, cos_falloff_start_;
};

// {"type": "spot", "position": [..], "look_at": [..] (or "direction": [..]), "intensity": [r, g, b],
//  "cone_angle_degrees": 30, "falloff_start_degrees": 20}
std::unique_ptr<Light> make_spot_light(const Parameters& p);

}  // namespace freezeray::ch03
