// Image textures: texels read from a file, filtered bilinearly, repeated (or clamped, or
// mirrored) outside the unit square.
#pragma once

#include "freezeray/ch02/texture.hpp"
#include "freezeray/ch02/texture_storage.hpp"

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace freezeray::ch02 {

// What happens to texture coordinates outside [0, 1]: the image repeats, its edge texels
// stretch out, or it repeats mirrored so that neighbouring copies meet without a seam.
enum class WrapMode { Repeat, Clamp, Mirror };

// The mode called `name` ("repeat", "clamp", "mirror"), or nothing for any other name.
std::optional<WrapMode> wrap_mode_from_name(const std::string& name);
std::vector<std::string> wrap_mode_names();

// The texel index that index i (any integer) stands for in a row of n texels.
int wrap_texel_index(int i, int n, WrapMode wrap);

// The bilinearly filtered value of `storage` at uv. Texel (x, y) covers [x, x+1] x [y, y+1] in
// texel units, so its centre is at (x + 1/2, y + 1/2); v is flipped so that v = 0 is the
// bottom row of the image, as OBJ texture coordinates expect. (Heckbert, "What Are the
// Coordinates of a Pixel?", Graphics Gems, 1990; Pharr, Jakob and Humphreys, "Physically Based
// Rendering", 4th ed., section 10.4.)
Spectrum bilinear_lookup(const TextureStorage& storage, const Vec2& uv, WrapMode wrap);

// How the 8-bit values of a PNG or JPEG file are meant. A colour map (an albedo) is sRGB
// encoded and decoded to linear values; a data map (roughness, a mix weight) holds the
// numbers themselves. Floating-point files (EXR, PFM, HDR) always hold linear values.
enum class TextureEncoding { SRGB, Linear };

std::optional<TextureEncoding> texture_encoding_from_name(const std::string& name);  // "srgb", "linear"

// The texels of the image file at `path`, read as `encoding` says. Every file is read once:
// later calls for the same file and encoding, while some texture still uses it, share the
// storage. Throws InputError naming the file if it cannot be read.
std::shared_ptr<const TextureStorage> load_texture_storage(const std::string& path, TextureEncoding encoding);

// A texture read from an image. A float texture takes the first (red) channel: data maps are
// grey images, whose three channels are equal, and a luminance of data has no meaning.
template <typename T>
class ImageTexture final : public Texture<T> {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, Spectrum>, "textures hold float or Spectrum");

public:
    ImageTexture(std::shared_ptr<const TextureStorage> storage, WrapMode wrap)
        : storage_(std::move(storage)), wrap_(wrap) {}

    T eval(const Vec2& uv) const override { return channels_of(bilinear_lookup(*storage_, uv, wrap_)); }

    T minimum() const override { return channels_of(storage_->minimum()); }
    T maximum() const override { return channels_of(storage_->maximum()); }

    const TextureStorage& storage() const { return *storage_; }
    WrapMode wrap() const { return wrap_; }

private:
    // The part of a texel value this texture returns.
    static T channels_of(const Spectrum& value) {
        if constexpr (std::is_same_v<T, float>) {
            return value.r;
        } else {
            return value;
        }
    }

    std::shared_ptr<const TextureStorage> storage_;
    WrapMode wrap_;
};

}  // namespace freezeray::ch02
