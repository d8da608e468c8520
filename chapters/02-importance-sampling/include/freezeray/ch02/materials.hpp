// The materials of chapter 02. A material holds its parameters (constants or textures); at a
// hit it evaluates them at the hit's texture coordinates and builds the BSDF there, in the
// path's scratch arena. The JSON parameters of each are listed in scenes/README.md.
#pragma once

#include "freezeray/ch02/material_parameters.hpp"
#include "freezeray/ch02/texture.hpp"
#include "freezeray/material.hpp"
#include "freezeray/parameters.hpp"

#include <functional>
#include <memory>

namespace freezeray::ch02 {

// A Lambertian reflector with a (possibly textured) albedo, sampled by cosine. It replaces
// chapter 01's freezeray::DiffuseMaterial, whose BSDF samples the hemisphere uniformly.
class DiffuseMaterial final : public Material {
public:
    explicit DiffuseMaterial(SpectrumTexture albedo) : albedo_(std::move(albedo)) {}
    const BSDF* bsdf(const Hit& hit, ScratchArena& arena) const override;
    std::uint32_t flags() const override { return BSDF_Reflection | BSDF_Diffuse; }
    bool is_textured() const override { return !albedo_->is_constant(); }

private:
    SpectrumTexture albedo_;
};

// A perfect mirror reflecting the fraction `reflectance` at every angle.
class MirrorMaterial final : public Material {
public:
    explicit MirrorMaterial(SpectrumTexture reflectance) : reflectance_(std::move(reflectance)) {}
    const BSDF* bsdf(const Hit& hit, ScratchArena& arena) const override;
    std::uint32_t flags() const override { return BSDF_Reflection | BSDF_Specular; }
    bool is_textured() const override { return !reflectance_->is_constant(); }

private:
    SpectrumTexture reflectance_;
};

// What a metal reflects, in one of two ways. Either its complex index of refraction eta + i k
// (measured, or a preset), whose Fresnel reflectance is then tinted by `specular_reflectance`;
// or, for an MTL file that gives only Ks, the reflectance at normal incidence R0 = Ks, from
// which an index with k = 0 is derived (see index_for_normal_reflectance).
class ConductorReflectance {
public:
    static ConductorReflectance from_index(const Spectrum& eta, const Spectrum& k, SpectrumTexture tint);
    static ConductorReflectance from_normal_reflectance(SpectrumTexture normal_reflectance);

    struct AtPoint {
        Spectrum eta;
        Spectrum k;
        Spectrum tint;  // multiplies the Fresnel reflectance; 1 when untinted
    };
    AtPoint at(const TextureLookup& lookup) const;

    bool is_textured() const { return !reflectance_->is_constant(); }

private:
    ConductorReflectance(const Spectrum& eta, const Spectrum& k, SpectrumTexture reflectance, bool is_normal_reflectance)
        : eta_(eta), k_(k), reflectance_(std::move(reflectance)), is_normal_reflectance_(is_normal_reflectance) {}

    Spectrum eta_;
    Spectrum k_;
    SpectrumTexture reflectance_;  // the tint, or R0 when is_normal_reflectance_
    bool is_normal_reflectance_;
};

// The real index of refraction (k = 0) whose Fresnel reflectance at normal incidence is r0,
// per channel: r0 = ((eta - 1) / (eta + 1))^2 solved for eta.
Spectrum index_for_normal_reflectance(const Spectrum& r0);

// A metal, smooth ("conductor": roughness 0) or rough ("roughconductor", GGX microfacets).
class ConductorMaterial final : public Material {
public:
    ConductorMaterial(ConductorReflectance reflectance, MicrofacetRoughness roughness)
        : reflectance_(std::move(reflectance)), roughness_(std::move(roughness)) {}
    const BSDF* bsdf(const Hit& hit, ScratchArena& arena) const override;
    std::uint32_t flags() const override { return BSDF_Reflection | roughness_.lobe_flags(); }
    bool is_textured() const override { return reflectance_.is_textured() || roughness_.is_textured(); }

private:
    ConductorReflectance reflectance_;
    MicrofacetRoughness roughness_;
};

// Glass: a dielectric interface with relative index eta = n_inside / n_outside, smooth
// ("dielectric") or rough ("roughdielectric").
class DielectricMaterial final : public Material {
public:
    DielectricMaterial(float eta, MicrofacetRoughness roughness) : eta_(eta), roughness_(std::move(roughness)) {}
    const BSDF* bsdf(const Hit& hit, ScratchArena& arena) const override;
    std::uint32_t flags() const override { return BSDF_Reflection | BSDF_Transmission | roughness_.lobe_flags(); }
    bool is_textured() const override { return roughness_.is_textured(); }

private:
    float eta_;
    MicrofacetRoughness roughness_;
};

// A diffuse base under a dielectric coating of index eta, smooth ("plastic") or rough
// ("roughplastic").
class PlasticMaterial final : public Material {
public:
    PlasticMaterial(SpectrumTexture albedo, float eta, MicrofacetRoughness roughness)
        : albedo_(std::move(albedo)), eta_(eta), roughness_(std::move(roughness)) {}
    const BSDF* bsdf(const Hit& hit, ScratchArena& arena) const override;
    std::uint32_t flags() const override { return BSDF_Reflection | BSDF_Diffuse | roughness_.lobe_flags(); }
    bool is_textured() const override { return !albedo_->is_constant() || roughness_.is_textured(); }

private:
    SpectrumTexture albedo_;
    float eta_;
    MicrofacetRoughness roughness_;
};

// A blend of two materials: at each point, `second` with probability `weight`, else `first`.
class MixMaterial final : public Material {
public:
    MixMaterial(std::shared_ptr<const Material> first, std::shared_ptr<const Material> second, FloatTexture weight)
        : first_(std::move(first)), second_(std::move(second)), weight_(std::move(weight)) {}
    const BSDF* bsdf(const Hit& hit, ScratchArena& arena) const override;
    std::uint32_t flags() const override { return first_->flags() | second_->flags(); }
    bool is_textured() const override {
        return first_->is_textured() || second_->is_textured() || !weight_->is_constant();
    }

private:
    std::shared_ptr<const Material> first_;
    std::shared_ptr<const Material> second_;
    FloatTexture weight_;
};

// Factories: each reads its JSON parameters and throws InputError naming the JSON path of a
// wrong one. `rough` selects the rough variant, which also reads the roughness.
std::unique_ptr<Material> make_diffuse_material(const Parameters& p, const MaterialContext& context);
std::unique_ptr<Material> make_mirror_material(const Parameters& p, const MaterialContext& context);
std::unique_ptr<Material> make_conductor_material(const Parameters& p, const MaterialContext& context, bool rough);
std::unique_ptr<Material> make_dielectric_material(const Parameters& p, const MaterialContext& context, bool rough);
std::unique_ptr<Material> make_plastic_material(const Parameters& p, const MaterialContext& context, bool rough);

// Builds a material from its JSON description (one part of a mix).
using MaterialBuilder = std::function<std::unique_ptr<Material>(const Parameters&, const MaterialContext&)>;

// A mix of the materials described inline by "first" and "second", built by `build_part`.
std::unique_ptr<Material> make_mix_material(const Parameters& p, const MaterialContext& context, const MaterialBuilder& build_part);

}  // namespace freezeray::ch02
