// PNG, and JPEG, BMP and TGA for reading: 8-bit sRGB images through Sean Barrett's stb_image
// and stb_image_write. Debian's libstb already contains their implementations, so we only
// include the declarations (no STB_IMAGE_IMPLEMENTATION here).
#include "freezeray/error.hpp"
#include "image_io_formats.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <memory>
#include <string>

namespace freezeray::image_io {

namespace {

// Frees pixels that stb_image allocated.
struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

// Why stb_image failed, for messages.
std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    return reason != nullptr ? reason : "unknown error";
}

// True for a PNG file (by its 8-byte signature) that lacks its closing IEND chunk: stb_image
// would decode what it finds, so a file cut short could otherwise pass for a complete one.
bool is_truncated_png(const Bytes& bytes) {
    const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 8 || !std::equal(signature, signature + 8, bytes.begin())) return false;
    const unsigned char end_chunk[4] = {'I', 'E', 'N', 'D'};
    const auto found = std::find_end(bytes.begin(), bytes.end(), end_chunk, end_chunk + 4);
    return found == bytes.end() || bytes.end() - found < 8;  // the chunk type, then its 4-byte CRC
}

// One channel as an 8-bit sRGB code value, after clamping to [0, 1].
unsigned char to_srgb_byte(float linear) {
    if (!(linear > 0.0f)) return 0;  // also catches NaN
    if (linear >= 1.0f) return 255;
    return static_cast<unsigned char>(std::lround(255.0f * linear_to_srgb(linear)));
}

// stb_image_write hands us the encoded file in pieces; we append them to a byte vector.
void append_to_bytes(void* context, void* data, int size) {
    auto* bytes = static_cast<Bytes*>(context);
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes->insert(bytes->end(), begin, begin + size);
}

}  // namespace

// Decodes an 8- or 16-bit PNG, JPEG, BMP or TGA file from sRGB to linear, dropping any alpha.
Image decode_srgb(const Bytes& bytes, const std::string& path) {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) {
        throw InputError(path, "the file is too large for the image decoder");
    }
    const int length = static_cast<int>(bytes.size());
    if (stbi_is_hdr_from_memory(bytes.data(), length) != 0) {
        // stb would quietly tone-map it to 8 bits; the user surely wanted the radiance.
        throw InputError(path, "contains Radiance HDR data; name it .hdr to read it as such");
    }
    if (is_truncated_png(bytes)) {
        throw InputError(path, "the PNG file is truncated (its final IEND chunk is missing)");
    }
    // Check the size in the header before stb allocates anything.
    int width = 0, height = 0, channels = 0;
    if (stbi_info_from_memory(bytes.data(), length, &width, &height, &channels) == 0) {
        throw InputError(path, "not a valid PNG, JPEG, BMP or TGA file (" + stb_reason() + ")");
    }
    check_image_size(width, height, path);

    Image image;
    if (stbi_is_16_bit_from_memory(bytes.data(), length) != 0) {
        std::unique_ptr<stbi_us, StbFree> pixels(
            stbi_load_16_from_memory(bytes.data(), length, &width, &height, &channels, 3));
        if (!pixels) {
            throw InputError(path, "cannot decode the image (" + stb_reason() + ")");
        }
        image = Image(width, height);
        const stbi_us* code = pixels.get();
        for (Spectrum& pixel : image.pixels()) {
            for (int c = 0; c < 3; ++c) pixel[c] = srgb_to_linear(static_cast<float>(*code++) / 65535.0f);
        }
    } else {
        std::unique_ptr<stbi_uc, StbFree> pixels(
            stbi_load_from_memory(bytes.data(), length, &width, &height, &channels, 3));
        if (!pixels) {
            throw InputError(path, "cannot decode the image (" + stb_reason() + ")");
        }
        float to_linear[256];  // decode each of the 256 code values once
        for (int code = 0; code < 256; ++code) to_linear[code] = srgb_to_linear(static_cast<float>(code) / 255.0f);
        image = Image(width, height);
        const stbi_uc* code = pixels.get();
        for (Spectrum& pixel : image.pixels()) {
            for (int c = 0; c < 3; ++c) pixel[c] = to_linear[*code++];
        }
    }
    return image;
}

// Encodes an 8-bit sRGB PNG of the radiance scaled by 2^exposure_stops and clamped to [0, 1].
Bytes encode_png(const Image& image, float exposure_stops, const std::string& path) {
    const float scale = std::exp2(exposure_stops);
    std::vector<unsigned char> codes;
    codes.reserve(image.pixel_count() * 3);
    for (const Spectrum& pixel : image.pixels()) {
        for (int c = 0; c < 3; ++c) codes.push_back(to_srgb_byte(pixel[c] * scale));
    }
    Bytes bytes;
    const int row_bytes = image.width() * 3;
    if (stbi_write_png_to_func(append_to_bytes, &bytes, image.width(), image.height(), 3, codes.data(), row_bytes) ==
        0) {
        throw InputError(path, "cannot encode the image as PNG");
    }
    return bytes;
}

}  // namespace freezeray::image_io
