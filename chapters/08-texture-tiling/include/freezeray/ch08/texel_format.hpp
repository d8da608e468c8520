// Texel formats: how one texel is kept in memory. Three 32-bit floats hold any value (12 bytes a
// texel); an image read from an 8-bit file holds at most 256 values per channel, so one byte per
// channel, decoded through a table on every lookup, holds it exactly in 4 bytes (the fourth is
// padding, so that a texel never straddles two cache lines and a 4 x 4 tile fills one 64-byte line).
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/math.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace freezeray::ch08 {

// 32-bit float channels: any value, 12 bytes a texel.
struct FloatTexels {
    struct Stored {
        float rgb[3];
    };
    static constexpr const char* name = "float";

    Stored encode(const Spectrum& value) const { return Stored{{value.r, value.g, value.b}}; }
    Spectrum decode(const Stored& texel) const { return Spectrum(texel.rgb[0], texel.rgb[1], texel.rgb[2]); }
};

// What the 256 codes of a byte stand for, in increasing order, and an index for the way back.
struct ByteDecoding {
    // The index's buckets split [0, 1) into equal parts; bucket b starts at b / IndexBuckets.
    static constexpr int IndexBuckets = 4096;

    const char* name;
    std::array<float, 256> value;
    // For each bucket, the highest code whose value lies below the bucket's start (0 if none):
    // where the search for the code nearest a value in the bucket may begin, a step or two
    // below the answer instead of a binary search over all 256 (encoding a scene's textures
    // was half of Sponza's loading time).
    std::array<std::uint8_t, IndexBuckets> search_start;
};

// srgb_to_linear(c / 255): what read_image makes of an 8-bit colour file.
const ByteDecoding& srgb_byte_decoding();
// linear_to_srgb(srgb_to_linear(c / 255)): a data map (roughness, a mix weight) read from an
// 8-bit file, after chapter 02's read_texture_image gave back its stored values.
const ByteDecoding& data_byte_decoding();

// The decodings an image from an 8-bit file may have been read with, in the order a layout
// tries them: the first whose table holds every texel exactly (bit for bit) keeps the image in
// bytes; when neither does (a floating-point or 16-bit file) it is kept in floats.
std::array<const ByteDecoding*, 2> byte_decodings();

// One byte per channel and one of padding: 4 bytes a texel.
struct ByteTexels {
    struct Stored {
        std::uint8_t code[4];
    };
    static constexpr const char* name = "8-bit";

    const ByteDecoding* decoding;

    // The nearest code per channel: exact for texels of the image the decoding was chosen for,
    // rounded for the averages of its MIP levels.
    Stored encode(const Spectrum& value) const;
    // The codes of `value` when the table holds each channel exactly (bit for bit), else nothing.
    std::optional<Stored> encode_exactly(const Spectrum& value) const;
    Spectrum decode(const Stored& texel) const {
        return Spectrum(decoding->value[texel.code[0]], decoding->value[texel.code[1]], decoding->value[texel.code[2]]);
    }
};

}  // namespace freezeray::ch08
