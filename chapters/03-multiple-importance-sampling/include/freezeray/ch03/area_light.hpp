// An area light: one emissive triangle, emitting Le uniformly from its front side (the side its
// counter-clockwise winding faces, as in chapter 01's one-sided emitters).
#pragma once

#include "freezeray/light.hpp"
#include "freezeray/mesh.hpp"

#include <array>

namespace freezeray::ch03 {

// Converts a density over the light's area to a density over solid angle as seen from the
// reference point: dA = r^2 / |cos theta_light| d omega (Veach 1997, eq. 8.10).
float area_to_solid_angle_pdf(float pdf_area, float distance_squared, float cos_light);

class TriangleLight final : public Light {
public:
    TriangleLight(const TriangleMesh& mesh, std::uint32_t triangle, const Spectrum& emission);

    LightType type() const override { return LightType::Area; }
    std::optional<LightSample> sample_li(const Vec3& reference, const Vec2& u) const override;
    float pdf_li(const Vec3& reference, const Vec3& wi) const override;
    std::optional<LightEmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction) const override;
    EmissionDensity pdf_le(const Ray& ray, const Vec3& normal) const override;
    Spectrum power() const override;

    float area() const { return area_; }
    const Vec3& normal() const { return normal_; }
    std::array<Vec3, 3> vertices() const { return {p0_, p1_, p2_}; }
    const Spectrum& emission() const { return emission_; }  // radiance, on the normal's side

private:
    Vec3 p0_, p1_, p2_;
    Vec3 normal_;  // unit, from the winding
    float area_;
    Spectrum emission_;
};

}  // namespace freezeray::ch03
