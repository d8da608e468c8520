// Environment lights: radiance arriving from infinitely far away in every direction. An
// equirectangular image, importance sampled by its brightness (pbrt-v3, section 14.2.4), and a
// constant colour.
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/light.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/ch03/piecewise_constant.hpp"

#include <memory>

namespace freezeray::ch03 {

// The equirectangular parametrisation, in the light's own frame (y up): u = phi / 2 pi with
// phi = atan2(x, -z) in [0, 2 pi), measured around +y from -z towards +x; v = theta / pi with
// theta measured from +y. The image's left and right edges look along -z, its centre column along
// +z, +x a quarter of the width from the left; its top row looks straight up.
Vec2 direction_to_equirectangular(const Vec3& direction);
Vec3 equirectangular_to_direction(const Vec2& uv);

// The solid-angle density of a direction whose (u, v) was drawn with density pdf_uv:
// d omega = sin theta d theta d phi = 2 pi^2 sin theta du dv (pbrt-v3, eq. 14.8).
float equirectangular_to_solid_angle_pdf(float pdf_uv, float sin_theta);

class EnvironmentMapLight final : public Light {
public:
    // light_to_world: a rotation. The image must be finite and non-negative.
    EnvironmentMapLight(Image image, const Spectrum& scale, const Mat3& light_to_world);

    LightType type() const override { return LightType::Infinite; }
    std::optional<LightSample> sample_li(const Vec3& reference, const Vec2& u) const override;
    float pdf_li(const Vec3& reference, const Vec3& wi) const override;
    Spectrum le(const Vec3& direction) const override;
    std::optional<LightEmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction) const override;
    EmissionDensity pdf_le(const Ray& ray, const Vec3& normal) const override;
    Spectrum power() const override;
    void preprocess(const Bounds3& scene_bounds) override;

private:
    // The image's value at (u, v), nearest pixel: the radiance is piecewise constant, exactly
    // the function the sampling distribution follows.
    Spectrum lookup(const Vec2& uv) const;

    Image image_;
    Spectrum scale_;
    Mat3 light_to_world_, world_to_light_;
    PiecewiseConstant2D distribution_;
    Vec3 scene_center_{0.0f};
    float scene_radius_ = 0.0f;
};

class ConstantEnvironmentLight final : public Light {
public:
    explicit ConstantEnvironmentLight(const Spectrum& radiance) : radiance_(radiance) {}

    LightType type() const override { return LightType::Infinite; }
    std::optional<LightSample> sample_li(const Vec3& reference, const Vec2& u) const override;
    float pdf_li(const Vec3& reference, const Vec3& wi) const override;
    Spectrum le(const Vec3&) const override { return radiance_; }
    std::optional<LightEmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction) const override;
    EmissionDensity pdf_le(const Ray& ray, const Vec3& normal) const override;
    Spectrum power() const override;
    void preprocess(const Bounds3& scene_bounds) override;

private:
    Spectrum radiance_;
    Vec3 scene_center_{0.0f};
    float scene_radius_ = 0.0f;
};

// {"type": "environment", "file": "sky.hdr", "scale": 1 or [r, g, b],
//  "rotate": {"axis": [0, 1, 0], "degrees": 90}}
std::unique_ptr<Light> make_environment_map_light(const Parameters& p);
// {"type": "constant", "radiance": [r, g, b]}
std::unique_ptr<Light> make_constant_environment_light(const Parameters& p);

}  // namespace freezeray::ch03
