// The encoders and decoders behind read_image and write_image, one file per format. Each works
// on bytes in memory, so that image_io.cpp alone deals with files (reading, atomic writing).
// Every function throws InputError(path, reason); `path` is only used in messages.
#pragma once

#include "freezeray/image.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace freezeray::image_io {

using Bytes = std::vector<unsigned char>;

// The most pixels a file may declare (2^28, a 16384 x 16384 image): a corrupt or hostile header
// must not make us allocate gigabytes.
inline constexpr std::int64_t MaxPixelCount = std::int64_t(1) << 28;

// Throws InputError unless width x height is a size we are willing to allocate (both positive,
// product at most MaxPixelCount). Takes 64-bit values so that the product cannot overflow.
void check_image_size(std::int64_t width, std::int64_t height, const std::string& path);

// OpenEXR through the OpenEXR library (image_io_exr.cpp).
Image decode_exr(const Bytes& bytes, const std::string& path);
Bytes encode_exr(const Image& image, const std::string& path);

// Portable float map, our own code (image_io_pfm.cpp).
Image decode_pfm(const Bytes& bytes, const std::string& path);
Bytes encode_pfm(const Image& image);

// Radiance HDR: our own reader, stb_image_write's writer (image_io_hdr.cpp).
Image decode_hdr(const Bytes& bytes, const std::string& path);
Bytes encode_hdr(const Image& image, const std::string& path);

// PNG (and JPEG, BMP, TGA for reading) through stb_image (image_io_png.cpp).
Image decode_srgb(const Bytes& bytes, const std::string& path);
Bytes encode_png(const Image& image, float exposure_stops, const std::string& path);

}  // namespace freezeray::image_io
