// Reading the parameters the materials share: values that may be textures, the index of
// refraction, the microfacet roughness. Every error names the JSON path of the value.
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/ch02/microfacet.hpp"
#include "freezeray/ch02/texture.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/registry.hpp"

#include <cstdint>
#include <string>

namespace freezeray::ch02 {

// A colour parameter: "key": a number or [r, g, b], or "key_texture": an image file, either
// its name or {"file": name, "wrap": "repeat" | "clamp" | "mirror", "encoding": "srgb" |
// "linear", "layout": a texture layout} (defaults: repeat, srgb, the scene's layout; "encoding"
// as in pbrt-v4's image textures). A texture
// replaces the constant (as Blender's OBJ importer treats Kd and map_Kd). Every channel of the
// constant and of every texel must lie in [min, max].
SpectrumTexture read_spectrum_texture(const Parameters& p, const MaterialContext& context, const std::string& key, const Spectrum& fallback,
                                      float min, float max);

// A number parameter, the same way: "key" or "key_texture", whose encoding defaults to linear
// (data, not colour) and whose first channel is used.
FloatTexture read_float_texture(const Parameters& p, const MaterialContext& context, const std::string& key, float fallback, float min, float max);

// "ior": the index of refraction of the inside relative to the outside, in (0, 10].
float read_index_of_refraction(const Parameters& p, float fallback);

// The roughness of a microfacet surface (Trowbridge-Reitz, or GGX). Given as "roughness"
// (isotropic, optionally with "anisotropy" in [0, 1]) or as "roughness_u" and "roughness_v"
// (along the tangent and the bitangent), each a number in [0, 1] or a texture; alpha =
// roughness^2 (Burley 2012, "Physically-Based Shading at Disney", section 5.4).
class MicrofacetRoughness {
public:
    MicrofacetRoughness(FloatTexture roughness_u, FloatTexture roughness_v, float anisotropy);

    // The microfacet distribution where the roughness textures are looked up.
    TrowbridgeReitz distribution(const TextureLookup& lookup) const;

    // The lobes this roughness can produce anywhere: BSDF_Glossy where the surface is rough,
    // BSDF_Specular where it is effectively smooth (the material then builds the smooth BSDF).
    std::uint32_t lobe_flags() const;

    bool is_textured() const { return !roughness_u_->is_constant() || !roughness_v_->is_constant(); }

private:
    TrowbridgeReitz distribution(float roughness_u, float roughness_v) const;

    FloatTexture roughness_u_;
    FloatTexture roughness_v_;
    float anisotropy_;
};

// The roughness of a rough material whose scene gives none: alpha = 0.09, a satin finish
// (near Mitsuba's default alpha of 0.1).
inline constexpr float DefaultRoughness = 0.3f;

// Roughness 0 everywhere: the smooth variants of the materials.
MicrofacetRoughness smooth_roughness();

// Reads "roughness" (default `fallback`), "anisotropy", or "roughness_u" and "roughness_v".
MicrofacetRoughness read_microfacet_roughness(const Parameters& p, const MaterialContext& context, float fallback);

// Throws InputError if the object has keys that nothing read (nested objects, such as a
// texture's or a mix's parts, have no other way to report a misspelt key).
void refuse_unknown_keys(const Parameters& p);

}  // namespace freezeray::ch02
