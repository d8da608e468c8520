// The ideal diffuse (Lambertian) reflector, the one material of chapter 01.
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/material.hpp"

namespace freezeray::ch01 {

// f = albedo / pi on the side of the shading normal; reflection only.
class LambertianBSDF final : public BSDF {
public:
    explicit LambertianBSDF(const Spectrum& albedo) : albedo_(albedo) {}

    Spectrum eval(const Vec3& wo, const Vec3& wi) const override;
    // Chapter 01 has no importance sampling yet: wi is uniform over the hemisphere of wo.
    // Chapter 02 registers a cosine-weighted "diffuse" in its place.
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    std::uint32_t flags() const override { return BSDF_Reflection | BSDF_Diffuse; }

    const Spectrum& albedo() const { return albedo_; }

private:
    Spectrum albedo_;
};

// A surface with a constant diffuse albedo (MTL Kd), possibly emitting (MTL Ke).
class DiffuseMaterial final : public Material {
public:
    explicit DiffuseMaterial(const Spectrum& albedo) : albedo_(albedo) {}
    const BSDF* bsdf(const Hit& hit, ScratchArena& arena) const override;
    std::uint32_t flags() const override { return BSDF_Reflection | BSDF_Diffuse; }

private:
    Spectrum albedo_;
};

}  // namespace freezeray::ch01
