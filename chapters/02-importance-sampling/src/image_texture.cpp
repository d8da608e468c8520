// Image textures: wrap mode names, and reading each file once.
#include "freezeray/ch02/image_texture.hpp"

#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/registry.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <tuple>
#include <utility>

namespace freezeray::ch02 {

std::optional<WrapMode> wrap_mode_from_name(const std::string& name) {
    if (name == "repeat") return WrapMode::Repeat;
    if (name == "clamp") return WrapMode::Clamp;
    if (name == "mirror") return WrapMode::Mirror;
    return std::nullopt;
}

std::vector<std::string> wrap_mode_names() { return {"repeat", "clamp", "mirror"}; }

std::optional<TextureEncoding> texture_encoding_from_name(const std::string& name) {
    if (name == "srgb") return TextureEncoding::SRGB;
    if (name == "linear") return TextureEncoding::Linear;
    return std::nullopt;
}

namespace {

// True for the formats read_image decodes from 8-bit sRGB (see common/image-files/src/image_io.cpp).
bool is_srgb_encoded_file(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".png" || extension == ".jpg" || extension == ".jpeg" || extension == ".bmp" ||
           extension == ".tga";
}

// Reads the image and, for a data map in an 8-bit file, undoes the sRGB decoding that
// read_image applied, giving back the stored values c / 255. (A `raw` option of read_image
// would save the round trip; the round trip is exact to about 1e-6.) Refuses texels that are
// not finite (a floating-point file may hold NaN or infinity), naming the first.
Image read_texture_image(const std::string& path, TextureEncoding encoding) {
    Image image = read_image(path);
    if (encoding == TextureEncoding::Linear && is_srgb_encoded_file(path))
        for (Spectrum& texel : image.pixels())
            for (int c = 0; c < 3; ++c) texel[c] = linear_to_srgb(texel[c]);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const Spectrum& texel = image.at(x, y);
            if (!std::isfinite(texel.r) || !std::isfinite(texel.g) || !std::isfinite(texel.b))
                throw InputError(path, "texel (" + std::to_string(x) + ", " + std::to_string(y) +
                                           ") is not a finite number");
        }
    return image;
}

// The name under which a file is cached: its canonical path, so that "a/../t.png" and "t.png"
// are one file.
std::string canonical_name(const std::string& path) {
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
    return error ? std::filesystem::path(path).lexically_normal().string() : canonical.string();
}

}  // namespace

std::shared_ptr<const TextureStorage> load_texture_storage(const std::string& path, TextureEncoding encoding,
                                                           const Registry& registry, const std::string& layout,
                                                           const Parameters* settings) {
    // The cache holds weak pointers: a file stays in memory exactly as long as some texture
    // uses it, and a scene loaded later reads it afresh.
    static std::mutex mutex;
    static std::map<std::tuple<std::string, TextureEncoding, std::string, std::string>,
                    std::weak_ptr<const TextureStorage>>
        cache;

    const auto key = std::make_tuple(canonical_name(path), encoding, layout, settings != nullptr ? settings->json().dump() : "");
    const std::lock_guard<std::mutex> lock(mutex);
    if (auto shared = cache[key].lock()) return shared;
    std::shared_ptr<const TextureStorage> storage =
        registry.texture_storage_maker(layout, "texture layout", settings)(read_texture_image(path, encoding));
    cache[key] = storage;
    std::erase_if(cache, [](const auto& entry) { return entry.second.expired(); });
    return storage;
}

}  // namespace freezeray::ch02
