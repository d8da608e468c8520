// Image textures: texels read from a file, filtered bilinearly, repeated (or clamped, or
// mirrored) outside the unit square.
#pragma once

#include "freezeray/ch02/texture.hpp"
#include "freezeray/ch02/linear_layout.hpp"
#include "freezeray/parameters.hpp"

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace freezeray {
class Registry;
}

namespace freezeray::ch02 {

// The wrap mode called `name` ("repeat", "clamp", "mirror"), or nothing for any other name.
std::optional<WrapMode> wrap_mode_from_name(const std::string& name);
std::vector<std::string> wrap_mode_names();

// How the 8-bit values of a PNG or JPEG file are meant. A colour map (an albedo) is sRGB
// encoded and decoded to linear values; a data map (roughness, a mix weight) holds the
// numbers themselves. Floating-point files (EXR, PFM, HDR) always hold linear values.
enum class TextureEncoding { SRGB, Linear };

std::optional<TextureEncoding> texture_encoding_from_name(const std::string& name);  // "srgb", "linear"

// The texels of the image file at `path`, read as `encoding` says and stored in `layout` (a
// registered texture layout) with its `settings` (null: its defaults). Every file is read once
// per encoding, layout and settings: later calls, while some texture still uses it, share the
// storage. Throws InputError naming the file if it cannot be read, or naming the layout if
// `registry` has none of that name.
std::shared_ptr<const TextureStorage> load_texture_storage(const std::string& path, TextureEncoding encoding,
                                                           const Registry& registry, const std::string& layout,
                                                           const Parameters* settings = nullptr);

// A texture read from an image. A float texture takes the first (red) channel: data maps are
// grey images, whose three channels are equal, and a luminance of data has no meaning.
template <typename T>
class ImageTexture final : public Texture<T> {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, Spectrum>, "textures hold float or Spectrum");

public:
    ImageTexture(std::shared_ptr<const TextureStorage> storage, WrapMode wrap)
        : storage_(std::move(storage)), wrap_(wrap) {}

    T eval(const TextureLookup& lookup) const override { return channels_of(storage_->lookup(lookup, wrap_)); }

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
