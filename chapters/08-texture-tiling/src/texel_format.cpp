// The byte decodings, and choosing one that holds an image exactly.
#include "freezeray/ch08/texel_format.hpp"

#include <algorithm>
#include <bit>
#include <iterator>

namespace freezeray::ch08 {

namespace {

ByteDecoding make_decoding(const char* name, bool data) {
    ByteDecoding decoding{name, {}, {}};
    for (int code = 0; code < 256; ++code) {
        // The same expressions, in the same order, as image_io_png.cpp and chapter 02's
        // read_texture_image: the same floats, bit for bit.
        const float linear = srgb_to_linear(static_cast<float>(code) / 255.0f);
        decoding.value[static_cast<std::size_t>(code)] = data ? linear_to_srgb(linear) : linear;
    }
    for (int bucket = 0; bucket < ByteDecoding::IndexBuckets; ++bucket) {
        const float start = static_cast<float>(bucket) / static_cast<float>(ByteDecoding::IndexBuckets);
        int code = 0;
        while (code < 255 && decoding.value[static_cast<std::size_t>(code + 1)] < start) ++code;
        decoding.search_start[static_cast<std::size_t>(bucket)] = static_cast<std::uint8_t>(code);
    }
    return decoding;
}

// The code whose value is nearest `x` (the lower of two equally near). The table increases.
std::uint8_t nearest_code(const ByteDecoding& decoding, float x) {
    const auto& table = decoding.value;
    if (!(x > table[0])) return 0;  // at or below the first value, or NaN
    if (x >= table[255]) return 255;
    // Now table[0] < x < table[255]. From the bucket's start, the code just below x: the first
    // code at or above x is then the next one (as std::lower_bound would find it).
    const int bucket = std::clamp(static_cast<int>(x * static_cast<float>(ByteDecoding::IndexBuckets)), 0,
                                  ByteDecoding::IndexBuckets - 1);
    std::size_t below = decoding.search_start[static_cast<std::size_t>(bucket)];
    while (table[below + 1] < x) ++below;
    const std::size_t above = below + 1;
    return static_cast<std::uint8_t>(x - table[below] <= table[above] - x ? below : above);
}

}  // namespace

const ByteDecoding& srgb_byte_decoding() {
    static const ByteDecoding decoding = make_decoding("sRGB", false);
    return decoding;
}

const ByteDecoding& data_byte_decoding() {
    static const ByteDecoding decoding = make_decoding("data", true);
    return decoding;
}

std::array<const ByteDecoding*, 2> byte_decodings() { return {&srgb_byte_decoding(), &data_byte_decoding()}; }

ByteTexels::Stored ByteTexels::encode(const Spectrum& value) const {
    return Stored{{nearest_code(*decoding, value.r), nearest_code(*decoding, value.g), nearest_code(*decoding, value.b), 0}};
}

std::optional<ByteTexels::Stored> ByteTexels::encode_exactly(const Spectrum& value) const {
    const Stored stored = encode(value);
    for (int c = 0; c < 3; ++c)
        if (std::bit_cast<std::uint32_t>(decoding->value[stored.code[c]]) != std::bit_cast<std::uint32_t>(value[c]))
            return std::nullopt;
    return stored;
}

}  // namespace freezeray::ch08
