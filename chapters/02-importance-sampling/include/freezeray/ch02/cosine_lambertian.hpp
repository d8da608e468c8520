// Importance sampling the Lambertian BSDF: directions drawn with density proportional to
// cos(theta), the factor the rendering equation multiplies f by, so that every sample's weight
// f cos / pdf is exactly the albedo.
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/ch01/lambertian.hpp"

namespace freezeray::ch02 {

// A uniform point on the unit disk from u in [0,1)^2 by the concentric map, which keeps
// neighbouring points of the square neighbours on the disk (Shirley and Chiu, "A Low Distortion
// Map Between Disk and Square", JGT 2(3), 1997).
Vec2 sample_concentric_disk(const Vec2& u);

// A direction on the hemisphere around +z with density cos(theta) / pi (Malley's method).
Vec3 sample_cosine_hemisphere(const Vec2& u);
float cosine_hemisphere_pdf(float cos_theta);

// The Lambertian BSDF of chapter 01, sampled by cosine. eval is chapter 01's LambertianBSDF::eval
// (that class is final, so this one holds one and forwards to it rather than deriving from it).
class CosineLambertianBSDF final : public BSDF {
public:
    explicit CosineLambertianBSDF(const Spectrum& albedo) : lambertian_(albedo) {}

    Spectrum eval(const Vec3& wo, const Vec3& wi) const override { return lambertian_.eval(wo, wi); }
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    std::uint32_t flags() const override { return lambertian_.flags(); }

    const Spectrum& albedo() const { return lambertian_.albedo(); }

private:
    ch01::LambertianBSDF lambertian_;
};

}  // namespace freezeray::ch02
