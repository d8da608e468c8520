// Reading textured parameters, the index of refraction and the microfacet roughness.
#include "freezeray/ch02/material_parameters.hpp"

#include "freezeray/ch02/image_texture.hpp"
#include "freezeray/error.hpp"
#include "freezeray/registry.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace freezeray::ch02 {

namespace {

// A number as a person would write it: "0.5", not "0.500000".
std::string number_text(float value) {
    std::string text = std::to_string(value);
    text.erase(text.find_last_not_of('0') + 1);  // "0.500000" -> "0.5"
    if (!text.empty() && text.back() == '.') text.pop_back();
    return text;
}

// Throws InputError at `where` unless every channel of [lowest, highest] lies in [min, max].
void check_texture_range(const std::string& where, const Spectrum& lowest, const Spectrum& highest, int channels,
                         float min, float max) {
    for (int c = 0; c < channels; ++c)
        if (lowest[c] < min || highest[c] > max)
            throw InputError(where, "texel values from " + number_text(lowest[c]) + " to " + number_text(highest[c]) +
                                        " are outside [" + number_text(min) + ", " + number_text(max) + "]");
}

// The string at `key` (or `fallback`) turned into an enumerator by `from_name`; an InputError
// that lists the valid `names` when it names none.
template <typename Enum, typename FromName>
Enum read_choice(const Parameters& p, const std::string& key, const std::string& fallback, FromName from_name,
                 const std::vector<std::string>& names) {
    const std::string name = p.get_string(key, fallback);
    if (const std::optional<Enum> value = from_name(name)) return *value;
    std::string all;
    for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
    throw InputError(p.where(key), "unknown value '" + name + "' (did you mean '" + nearest_name(name, names) +
                                       "'?); valid: " + all);
}

// The image texture "key_texture" describes (a file name or an object), or nullptr when absent.
template <typename T>
std::shared_ptr<const Texture<T>> read_image_texture(const Parameters& p, const MaterialContext& context, const std::string& key,
                                                     TextureEncoding default_encoding, float min, float max) {
    const std::string texture_key = key + "_texture";
    if (!p.has(texture_key)) return nullptr;
    std::string file;
    WrapMode wrap = WrapMode::Repeat;
    TextureEncoding encoding = default_encoding;
    std::string layout = context.texture_layout;
    if (p.json().at(texture_key).is_object()) {
        const Parameters t = p.child(texture_key);
        file = t.require_existing_file("file");
        wrap = read_choice<WrapMode>(t, "wrap", "repeat", wrap_mode_from_name, wrap_mode_names());
        encoding = read_choice<TextureEncoding>(t, "encoding", default_encoding == TextureEncoding::SRGB ? "srgb" : "linear",
                                                texture_encoding_from_name, {"srgb", "linear"});
        // This texture's own layout, over the scene's (its "textures" block).
        layout = t.get_string("layout", layout);
        context.registry.require(CapabilityKind::TextureLayout, layout, t.where("layout"));
        refuse_unknown_keys(t);
    } else if (p.json().at(texture_key).is_string()) {
        file = p.require_existing_file(texture_key);
    } else {
        throw InputError(p.where(texture_key), "expected an image file name or an object {\"file\": ..., \"wrap\": ...}");
    }

    std::shared_ptr<const TextureStorage> storage;
    try {
        storage = load_texture_storage(file, encoding, context.registry, layout, context.texture_settings);
    } catch (const InputError& e) {
        throw InputError(p.where(texture_key), e.what());  // the JSON path, then the file's own message
    }
    if (context.loaded_textures != nullptr &&
        std::find(context.loaded_textures->begin(), context.loaded_textures->end(), storage) == context.loaded_textures->end())
        context.loaded_textures->push_back(storage);
    auto texture = std::make_shared<ImageTexture<T>>(std::move(storage), wrap);
    check_texture_range(p.where(texture_key), Spectrum(texture->minimum()), Spectrum(texture->maximum()),
                        std::is_same_v<T, float> ? 1 : 3, min, max);
    return texture;
}

}  // namespace

SpectrumTexture read_spectrum_texture(const Parameters& p, const MaterialContext& context, const std::string& key, const Spectrum& fallback, float min,
                                      float max) {
    // The constant is checked even when a texture replaces it (an MTL file gives both Kd and map_Kd).
    const Spectrum value = p.get_spectrum(key, fallback);
    for (int c = 0; c < 3; ++c) p.check_range(key, value[c], min, max);
    if (SpectrumTexture texture = read_image_texture<Spectrum>(p, context, key, TextureEncoding::SRGB, min, max)) return texture;
    return make_constant_texture(value);
}

FloatTexture read_float_texture(const Parameters& p, const MaterialContext& context, const std::string& key, float fallback, float min, float max) {
    const float value = p.check_range(key, p.get_float(key, fallback), min, max);
    if (FloatTexture texture = read_image_texture<float>(p, context, key, TextureEncoding::Linear, min, max)) return texture;
    return make_constant_texture(value);
}

float read_index_of_refraction(const Parameters& p, float fallback) {
    const float ior = p.get_float("ior", fallback);
    if (!(ior > 0.0f && ior <= 10.0f))
        throw InputError(p.where("ior"), "value " + number_text(ior) + " is outside (0, 10]");
    return ior;
}

MicrofacetRoughness::MicrofacetRoughness(FloatTexture roughness_u, FloatTexture roughness_v, float anisotropy)
    : roughness_u_(std::move(roughness_u)), roughness_v_(std::move(roughness_v)), anisotropy_(anisotropy) {}

TrowbridgeReitz MicrofacetRoughness::distribution(float roughness_u, float roughness_v) const {
    float alpha_u = TrowbridgeReitz::roughness_to_alpha(roughness_u);
    float alpha_v = TrowbridgeReitz::roughness_to_alpha(roughness_v);
    if (anisotropy_ > 0.0f) {
        // Burley 2012, "Physically-Based Shading at Disney", addendum B.2: stretch the
        // highlight along the tangent, keeping alpha_u * alpha_v = alpha^2.
        const float aspect = std::sqrt(1.0f - 0.9f * anisotropy_);
        alpha_u /= aspect;
        alpha_v *= aspect;
    }
    return TrowbridgeReitz(alpha_u, alpha_v);
}

TrowbridgeReitz MicrofacetRoughness::distribution(const TextureLookup& lookup) const {
    return distribution(roughness_u_->eval(lookup), roughness_v_->eval(lookup));
}

std::uint32_t MicrofacetRoughness::lobe_flags() const {
    // alpha grows with the roughness, so the extremes of the textures bound every distribution.
    std::uint32_t flags = 0;
    if (distribution(roughness_u_->minimum(), roughness_v_->minimum()).effectively_smooth()) flags |= BSDF_Specular;
    if (!distribution(roughness_u_->maximum(), roughness_v_->maximum()).effectively_smooth()) flags |= BSDF_Glossy;
    return flags;
}

MicrofacetRoughness smooth_roughness() {
    const FloatTexture zero = make_constant_texture(0.0f);
    return MicrofacetRoughness(zero, zero, 0.0f);
}

MicrofacetRoughness read_microfacet_roughness(const Parameters& p, const MaterialContext& context, float fallback) {
    const bool per_direction = p.has("roughness_u") || p.has("roughness_v") || p.has("roughness_u_texture") ||
                               p.has("roughness_v_texture");
    if (!per_direction) {
        FloatTexture roughness = read_float_texture(p, context, "roughness", fallback, 0.0f, 1.0f);
        const float anisotropy = p.check_range("anisotropy", p.get_float("anisotropy", 0.0f), 0.0f, 1.0f);
        return MicrofacetRoughness(roughness, roughness, anisotropy);
    }
    for (const char* isotropic : {"roughness", "roughness_texture", "anisotropy"})
        if (p.has(isotropic))
            throw InputError(p.where(isotropic), "give either 'roughness' (and 'anisotropy') or 'roughness_u' and "
                                                 "'roughness_v', not both");
    for (const char* direction : {"roughness_u", "roughness_v"})
        if (!p.has(direction) && !p.has(std::string(direction) + "_texture"))
            throw InputError(p.where(direction), "is required with the other of 'roughness_u' and 'roughness_v'");
    return MicrofacetRoughness(read_float_texture(p, context, "roughness_u", fallback, 0.0f, 1.0f),
                               read_float_texture(p, context, "roughness_v", fallback, 0.0f, 1.0f), 0.0f);
}

void refuse_unknown_keys(const Parameters& p) {
    const std::vector<std::string> warnings = p.unused_key_warnings();
    if (warnings.empty()) return;
    // The warning names the place, the key and the nearest known key; here it is an error.
    std::string message = warnings.front();
    const std::string ignored = " is ignored";
    if (const std::size_t at = message.find(ignored); at != std::string::npos) message.erase(at, ignored.size());
    throw InputError("", message);
}

}  // namespace freezeray::ch02
