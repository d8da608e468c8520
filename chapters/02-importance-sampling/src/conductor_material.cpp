// Metals: the perfect mirror, and smooth and rough conductors described by their complex index
// of refraction (or, from an MTL file, by their reflectance at normal incidence).
#include "freezeray/ch02/fresnel.hpp"
#include "freezeray/ch02/materials.hpp"
#include "freezeray/ch02/mirror.hpp"
#include "freezeray/ch02/rough_conductor.hpp"
#include "freezeray/ch02/specular_conductor.hpp"
#include "freezeray/error.hpp"
#include "freezeray/registry.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch02 {

namespace {

// A BSDF whose value is another's times a colour, sampled as that one is: how
// "specular_reflectance" tints a conductor (the tint is not a Fresnel effect, so it cannot be
// folded into eta and k). Lives in the arena beside the BSDF it tints.
class TintedBSDF final : public BSDF {
public:
    TintedBSDF(const BSDF* tinted, const Spectrum& tint) : tinted_(tinted), tint_(tint) {}

    Spectrum eval(const Vec3& wo, const Vec3& wi) const override { return tint_ * tinted_->eval(wo, wi); }
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override {
        std::optional<BSDFSample> s = tinted_->sample(wo, u, u_lobe);
        if (s) s->f *= tint_;
        return s;
    }
    float pdf(const Vec3& wo, const Vec3& wi) const override { return tinted_->pdf(wo, wi); }
    std::uint32_t flags() const override { return tinted_->flags(); }

private:
    const BSDF* tinted_;
    Spectrum tint_;
};

}  // namespace

const BSDF* MirrorMaterial::bsdf(const Hit& hit, ScratchArena& arena) const {
    return arena.make<MirrorBSDF>(reflectance_->eval(hit.texture_lookup()));
}

ConductorReflectance ConductorReflectance::from_index(const Spectrum& eta, const Spectrum& k, SpectrumTexture tint) {
    return ConductorReflectance(eta, k, std::move(tint), false);
}

ConductorReflectance ConductorReflectance::from_normal_reflectance(SpectrumTexture normal_reflectance) {
    return ConductorReflectance(Spectrum(1.0f), Spectrum(0.0f), std::move(normal_reflectance), true);
}

ConductorReflectance::AtPoint ConductorReflectance::at(const TextureLookup& lookup) const {
    const Spectrum reflectance = reflectance_->eval(lookup);
    if (is_normal_reflectance_) return {index_for_normal_reflectance(reflectance), Spectrum(0.0f), Spectrum(1.0f)};
    return {eta_, k_, reflectance};
}

// A choice for MTL files, which describe a metal only by Ks: a conductor with k = 0 matches Ks
// exactly at normal incidence and, like every Fresnel reflectance, rises to 1 at grazing
// angles, so it stays energy conserving (unlike Schlick's curve with its own R0, which is only
// an approximation of these equations). Real metals have k > 0 and a shallower dip before the
// rise; presets or "eta" and "k" give those. sqrt(r0) is kept below 0.999 (eta < 2000) so that
// r0 = 1 stays finite, reflecting 99.8 % at normal incidence.
Spectrum index_for_normal_reflectance(const Spectrum& r0) {
    Spectrum eta;
    for (int c = 0; c < 3; ++c) {
        const float root = std::min(std::sqrt(std::max(r0[c], 0.0f)), 0.999f);
        eta[c] = (1.0f + root) / (1.0f - root);  // r0 = ((eta - 1) / (eta + 1))^2
    }
    return eta;
}

// BOOK(conductor-material-bsdf)
const BSDF* ConductorMaterial::bsdf(const Hit& hit, ScratchArena& arena) const {
    const ConductorReflectance::AtPoint metal = reflectance_.at(hit.texture_lookup());
    const TrowbridgeReitz distribution = roughness_.distribution(hit.texture_lookup());
    // A surface too smooth for the microfacet model to sample well is a mirror-like delta lobe.
    const BSDF* bsdf = nullptr;
    if (distribution.effectively_smooth())
        bsdf = arena.make<SpecularConductorBSDF>(metal.eta, metal.k);
    else
        bsdf = arena.make<RoughConductorBSDF>(distribution, metal.eta, metal.k);
    if (metal.tint == Spectrum(1.0f)) return bsdf;
    return arena.make<TintedBSDF>(bsdf, metal.tint);
}
// END BOOK

std::unique_ptr<Material> make_mirror_material(const Parameters& p, const MaterialContext& context) {
    return std::make_unique<MirrorMaterial>(read_spectrum_texture(p, context, "reflectance", Spectrum(1.0f), 0.0f, 1.0f));
}

namespace {

// A colour of optical constants ("eta" or "k"), each channel in (lowest, 10] or [0, 10].
Spectrum read_optical_constant(const Parameters& p, const std::string& key, bool positive) {
    if (!p.has(key)) throw InputError(p.where(key), "is required: 'eta' and 'k' come together");
    const Spectrum value = p.get_spectrum(key, Spectrum(0.0f));
    for (int c = 0; c < 3; ++c)
        if (!(value[c] <= 10.0f && (positive ? value[c] > 0.0f : value[c] >= 0.0f)))
            throw InputError(p.where(key), "value " + std::to_string(value[c]) + " is outside " +
                                               (positive ? "(0, 10]" : "[0, 10]"));
    return value;
}

// "material" (a preset), or "eta" and "k", each tinted by "specular_reflectance"; or only
// "specular_reflectance", the reflectance at normal incidence (what an MTL file's Ks means).
ConductorReflectance read_conductor_reflectance(const Parameters& p, const MaterialContext& context) {
    const bool has_preset = p.has("material");
    const bool has_index = p.has("eta") || p.has("k");
    if (has_preset && has_index)
        throw InputError(p.where("material"), "give either a preset 'material' or 'eta' and 'k', not both");
    if (has_preset) {
        const std::string name = p.get_string("material", "");
        const ConductorPreset* preset = find_conductor_preset(name);
        if (!preset) {
            const std::vector<std::string> names = conductor_preset_names();
            std::string all;
            for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
            throw InputError(p.where("material"), "unknown conductor '" + name + "' (did you mean '" +
                                                      nearest_name(name, names) + "'?); presets: " + all);
        }
        return ConductorReflectance::from_index(preset->eta, preset->k,
                                                read_spectrum_texture(p, context, "specular_reflectance", Spectrum(1.0f), 0.0f, 1.0f));
    }
    if (has_index) {
        const Spectrum eta = read_optical_constant(p, "eta", true);
        const Spectrum k = read_optical_constant(p, "k", false);
        return ConductorReflectance::from_index(eta, k,
                                                read_spectrum_texture(p, context, "specular_reflectance", Spectrum(1.0f), 0.0f, 1.0f));
    }
    if (p.has("specular_reflectance") || p.has("specular_reflectance_texture"))
        return ConductorReflectance::from_normal_reflectance(
            read_spectrum_texture(p, context, "specular_reflectance", Spectrum(1.0f), 0.0f, 1.0f));
    std::string presets;
    for (const std::string& n : conductor_preset_names()) presets += (presets.empty() ? "" : ", ") + n;
    throw InputError(p.where("material"), "a conductor needs a preset 'material' (" + presets +
                                              "), or 'eta' and 'k', or 'specular_reflectance' (its reflectance at "
                                              "normal incidence)");
}

}  // namespace

std::unique_ptr<Material> make_conductor_material(const Parameters& p, const MaterialContext& context, bool rough) {
    ConductorReflectance reflectance = read_conductor_reflectance(p, context);
    MicrofacetRoughness roughness = rough ? read_microfacet_roughness(p, context, DefaultRoughness) : smooth_roughness();
    return std::make_unique<ConductorMaterial>(std::move(reflectance), std::move(roughness));
}

}  // namespace freezeray::ch02
