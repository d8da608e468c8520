// Image textures: wrap modes, bilinear filtering, and reading each file once.
#include "freezeray/ch02/image_texture.hpp"

#include "freezeray/error.hpp"
#include "freezeray/image.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
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

// BOOK(wrap-texel-index)
int wrap_texel_index(int i, int n, WrapMode wrap) {
    switch (wrap) {
        case WrapMode::Repeat: return ((i % n) + n) % n;  // C++'s % keeps the sign of i
        case WrapMode::Clamp: return std::clamp(i, 0, n - 1);
        case WrapMode::Mirror: {
            // Mirrored repetition has period 2n: n texels forwards, then the same n backwards.
            const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
            return m < n ? m : 2 * n - 1 - m;
        }
    }
    return 0;
}
// END BOOK

namespace {

// Moves a coordinate by whole periods of the wrap mode (which changes nothing) so that texel
// indices computed from it stay small: a uv of 1e9 would overflow an int. A coordinate that
// is not a number reads the texture at 0.
float reduce_to_one_period(float u, WrapMode wrap) {
    if (!std::isfinite(u)) return 0.0f;
    switch (wrap) {
        case WrapMode::Repeat: return u - std::floor(u);
        case WrapMode::Mirror: return u - 2.0f * std::floor(0.5f * u);
        case WrapMode::Clamp: return std::clamp(u, -1.0f, 2.0f);
    }
    return u;
}

}  // namespace

// BOOK(bilinear-lookup)
Spectrum bilinear_lookup(const TextureStorage& storage, const Vec2& uv, WrapMode wrap) {
    const int width = storage.width();
    const int height = storage.height();
    // Continuous texel coordinates: texel centres sit at half-integers, so subtracting 1/2
    // puts them on integers. Rows count down from the top of the image while v counts up.
    const float x = reduce_to_one_period(uv.x, wrap) * static_cast<float>(width) - 0.5f;
    const float y = (1.0f - reduce_to_one_period(uv.y, wrap)) * static_cast<float>(height) - 0.5f;
    const float x0 = std::floor(x);
    const float y0 = std::floor(y);
    const float dx = x - x0;  // weight of the right-hand column
    const float dy = y - y0;  // weight of the lower row

    const int left = wrap_texel_index(static_cast<int>(x0), width, wrap);
    const int right = wrap_texel_index(static_cast<int>(x0) + 1, width, wrap);
    const int top = wrap_texel_index(static_cast<int>(y0), height, wrap);
    const int bottom = wrap_texel_index(static_cast<int>(y0) + 1, height, wrap);

    return (1.0f - dx) * (1.0f - dy) * storage.texel(left, top) + dx * (1.0f - dy) * storage.texel(right, top) +
           (1.0f - dx) * dy * storage.texel(left, bottom) + dx * dy * storage.texel(right, bottom);
}
// END BOOK

namespace {

// True for the formats read_image decodes from 8-bit sRGB (see common/src/image_io.cpp).
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

std::shared_ptr<const TextureStorage> load_texture_storage(const std::string& path, TextureEncoding encoding) {
    // The cache holds weak pointers: a file stays in memory exactly as long as some texture
    // uses it, and a scene loaded later reads it afresh.
    static std::mutex mutex;
    static std::map<std::pair<std::string, TextureEncoding>, std::weak_ptr<const TextureStorage>> cache;

    const auto key = std::make_pair(canonical_name(path), encoding);
    const std::lock_guard<std::mutex> lock(mutex);
    if (auto shared = cache[key].lock()) return shared;
    std::shared_ptr<const TextureStorage> storage =
        std::make_shared<LinearTextureStorage>(read_texture_image(path, encoding));
    cache[key] = storage;
    std::erase_if(cache, [](const auto& entry) { return entry.second.expired(); });
    return storage;
}

}  // namespace freezeray::ch02
