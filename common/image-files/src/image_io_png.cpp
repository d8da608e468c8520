// PNG, and JPEG, BMP and TGA for reading: 8-bit sRGB images through Sean Barrett's stb_image
// and stb_image_write. Debian's libstb already contains their implementations, so we only
// include the declarations (no STB_IMAGE_IMPLEMENTATION here).
#include "freezeray/error.hpp"
#include "image_io_formats.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace freezeray::image_io {

namespace {

// The extension of `path` in lower case, with its dot.
std::string lowercase_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

// Frees pixels that stb_image allocated.
struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

// Why stb_image failed, for messages.
std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    return reason != nullptr ? reason : "unknown error";
}

// The 8-bit formats, told by their first bytes. TGA has no signature: it is what is left.
enum class Format { png, jpeg, bmp, unsupported, tga };

bool starts_with(const Bytes& bytes, std::string_view prefix) {
    return bytes.size() >= prefix.size() &&
           std::equal(prefix.begin(), prefix.end(), bytes.begin(),
                      [](char a, unsigned char b) { return static_cast<unsigned char>(a) == b; });
}

// Where the marker segments of a JPEG file begin, after its start-of-image marker; 0 when it
// has none. stb_image, like the JPEG standard (ITU T.81, B.1.1.2), lets fill bytes 0xFF precede
// a marker, so "FF FF D8" starts a JPEG file too.
std::size_t jpeg_data_start(const Bytes& bytes) {
    std::size_t i = 0;
    while (i < bytes.size() && bytes[i] == 0xff) ++i;
    return i > 0 && i < bytes.size() && bytes[i] == 0xd8 ? i + 1 : 0;
}

// The format stb_image will decode `bytes` as, by the signatures its loaders test for. GIF, PSD,
// Softimage PIC and PNM, which stb_image also reads, are "unsupported": they are not among
// the formats the renderer documents, and a truncated one would decode as black.
Format format_of(const Bytes& bytes) {
    using namespace std::string_view_literals;
    if (starts_with(bytes, "\x89PNG\r\n\x1a\n"sv)) return Format::png;
    if (jpeg_data_start(bytes) > 0) return Format::jpeg;
    if (starts_with(bytes, "BM"sv)) return Format::bmp;
    if (starts_with(bytes, "GIF8"sv) || starts_with(bytes, "8BPS"sv) || starts_with(bytes, "\x53\x80\xf6\x34"sv) ||
        starts_with(bytes, "P5"sv) || starts_with(bytes, "P6"sv))
        return Format::unsupported;
    return Format::tga;
}

std::uint32_t little_endian(const Bytes& bytes, std::size_t at, int size) {
    std::uint32_t value = 0;
    for (int i = size - 1; i >= 0; --i) value = (value << 8) | bytes[at + static_cast<std::size_t>(i)];
    return value;
}

// The stb_image of Debian 12 builds a Huffman table without checking that its 16 code counts
// add up to at most 256 codes (ITU T.81, B.2.4.2), and writes past the end of its arrays when
// they do not (found by fuzz_image; later stb_image versions check it). This walks the marker
// segments of a JPEG file (T.81, B.1.1.2: 0xFF, a code, a 2-byte big-endian length that counts
// itself) and refuses a DHT segment with such a table. Entropy-coded data after a scan is
// skipped up to the next marker (0xFF followed by neither 0 nor a restart code).
void check_jpeg_huffman_tables(const Bytes& bytes, const std::string& path) {
    std::size_t position = jpeg_data_start(bytes);
    while (position + 4 <= bytes.size()) {
        if (bytes[position] != 0xff) {  // entropy-coded data
            ++position;
            continue;
        }
        const unsigned char code = bytes[position + 1];
        if (code == 0xff || code == 0x00 || code == 0x01 || (code >= 0xd0 && code <= 0xd7)) {  // fill, stuffing, restarts
            position += code == 0xff ? 1 : 2;
            continue;
        }
        if (code == 0xd9) return;  // end of image
        const std::size_t length = (std::size_t(bytes[position + 2]) << 8) | bytes[position + 3];
        const std::size_t end = position + 2 + length;
        if (end > bytes.size())  // stb_image would read the missing bytes as zeros
            throw InputError(path, "the JPEG file is truncated (a marker segment runs past its end)");
        if (code == 0xc4) {
            for (std::size_t table = position + 4; table < end;) {
                if (end - table < 17) throw InputError(path, "not a valid JPEG file: a Huffman table is cut short");
                std::size_t codes = 0;
                for (std::size_t i = 1; i <= 16; ++i) codes += bytes[table + i];
                if (codes > 256)
                    throw InputError(path, "not a valid JPEG file: a Huffman table has " + std::to_string(codes) +
                                               " codes (at most 256)");
                table += 17 + codes;
            }
        }
        position = std::max(end, position + 4);
    }
}

// stb_image reads past the end of a file as zeros, so a truncated JPEG, BMP or TGA decodes
// without an error (found by fuzz_image: a 40-byte BMP header "decoding" as a large black
// image). These checks refuse a file that stops before its pixel data does. A PNG must end
// with its IEND chunk and a JPEG with its end-of-image marker; for BMP and TGA the header says
// how many bytes follow. Headers too short or odd to check are left to stb_image to refuse.
void check_complete(const Bytes& bytes, Format format, const std::string& path) {
    const auto truncated = [&](const char* name, const std::string& detail) {
        throw InputError(path, std::string("the ") + name + " file is truncated (" + detail + ")");
    };
    if (format == Format::png) {
        // Chunks: a 4-byte big-endian length, the type, the data, a CRC; the last is IEND. stb_image
        // grows its buffer to an IDAT chunk's stated length before reading it, so a length past
        // the end of the file must be refused first (found by fuzz_image: a 2 GB allocation).
        std::size_t position = 8;
        for (;;) {
            if (bytes.size() - position < 12) truncated("PNG", "its final IEND chunk is missing");
            std::uint32_t length = 0;
            for (int i = 0; i < 4; ++i) length = (length << 8) | bytes[position + static_cast<std::size_t>(i)];
            if (length > bytes.size() - position - 12) truncated("PNG", "a chunk runs past the end of the file");
            if (std::equal(bytes.begin() + static_cast<std::ptrdiff_t>(position) + 4,
                           bytes.begin() + static_cast<std::ptrdiff_t>(position) + 8, "IEND"))
                break;
            position += 12 + length;
        }
    } else if (format == Format::jpeg) {
        const unsigned char end_marker[2] = {0xff, 0xd9};
        if (std::find_end(bytes.begin() + static_cast<std::ptrdiff_t>(jpeg_data_start(bytes)), bytes.end(), end_marker,
                          end_marker + 2) == bytes.end())
            truncated("JPEG", "its end-of-image marker is missing");
        check_jpeg_huffman_tables(bytes, path);
    } else if (format == Format::bmp) {
        // BITMAPFILEHEADER (14 bytes), then an OS/2 header (12 bytes: 16-bit sizes) or a Windows
        // one (40 bytes or more: 32-bit sizes); rows are padded to 4 bytes, the last one possibly not.
        if (bytes.size() < 18) truncated("BMP", "its header is cut short");
        const std::uint32_t header_size = little_endian(bytes, 14, 4);
        const bool known = header_size == 12 || header_size == 40 || header_size == 56 || header_size == 108 ||
                           header_size == 124;
        if (!known) return;  // stb_image refuses it
        if (bytes.size() < 14 + header_size) truncated("BMP", "its header is cut short");
        const std::uint64_t offset = little_endian(bytes, 10, 4);
        const bool os2 = header_size == 12;
        const std::int64_t width = os2 ? little_endian(bytes, 18, 2) : static_cast<std::int32_t>(little_endian(bytes, 18, 4));
        std::int64_t height = os2 ? static_cast<std::int16_t>(little_endian(bytes, 20, 2))
                                  : static_cast<std::int32_t>(little_endian(bytes, 22, 4));
        const std::uint32_t bits = little_endian(bytes, os2 ? 24 : 28, 2);
        // stb_image refuses compression 1, 2 (run-length) and 4 or more, and reads the others,
        // negative ones included, as uncompressed rows.
        const auto compression = os2 ? 0 : static_cast<std::int32_t>(little_endian(bytes, 30, 4));
        height = height < 0 ? -height : height;
        if (compression == 1 || compression == 2 || compression >= 4 || width <= 0 || height == 0 || bits == 0 ||
            bits > 32)
            return;
        const std::uint64_t row = (static_cast<std::uint64_t>(width) * bits + 7) / 8;
        const std::uint64_t stride = (static_cast<std::uint64_t>(width) * bits + 31) / 32 * 4;
        const std::uint64_t needed = offset + stride * static_cast<std::uint64_t>(height - 1) + row;
        if (needed > bytes.size())
            truncated("BMP", "its header announces " + std::to_string(needed) + " bytes, the file has " +
                                 std::to_string(bytes.size()));
    } else if (format == Format::tga) {
        // The 18-byte header, an image id, a colour map, then the pixels: raw (types 1 to 3) or
        // run-length packets (types 9 to 11) of at most 128 pixels, each a count byte and one
        // pixel (a run) or that many pixels (raw).
        if (bytes.size() < 18) truncated("TGA", "its 18-byte header is cut short");
        const std::uint32_t type = bytes[2];
        const std::uint64_t map_bytes = bytes[1] != 0 ? little_endian(bytes, 5, 2) * ((bytes[7] + 7u) / 8u) : 0;
        std::uint64_t position = 18 + bytes[0] + map_bytes;
        const std::uint64_t pixels = std::uint64_t(little_endian(bytes, 12, 2)) * little_endian(bytes, 14, 2);
        const std::uint64_t pixel_bytes = (bytes[16] + 7u) / 8u;
        if (type >= 1 && type <= 3) {
            if (position + pixels * pixel_bytes > bytes.size()) truncated("TGA", "its pixel data ends early");
        } else if (type >= 9 && type <= 11) {
            for (std::uint64_t done = 0; done < pixels;) {
                if (position >= bytes.size()) truncated("TGA", "its run-length data ends early");
                const unsigned char packet = bytes[position++];
                const std::uint64_t count = (packet & 0x7fu) + 1u;
                position += (packet & 0x80u) != 0 ? pixel_bytes : count * pixel_bytes;
                if (position > bytes.size()) truncated("TGA", "its run-length data ends early");
                done += count;
            }
        }
    }
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

// A JPEG codes every 8x8 block of its image with at least one bit (a baseline block's DC and
// end-of-block codes, or a progressive DC scan's code), so a file shorter than blocks / 8 bytes
// cannot hold the image its header claims. stb_image would decode it anyway, as an image of
// zeros of the claimed size (found by fuzz_image: 662 bytes claiming 65531 x 2300 pixels, decoded
// into 1.8 GB over more than 10 seconds).
void check_jpeg_data_size(std::size_t file_size, int width, int height, const std::string& path) {
    const std::uint64_t blocks = static_cast<std::uint64_t>((width + 7) / 8) * static_cast<std::uint64_t>((height + 7) / 8);
    const std::uint64_t minimum = blocks / 8;
    if (file_size < minimum)
        throw InputError(path, "the JPEG header claims " + std::to_string(width) + "x" + std::to_string(height) +
                                   " pixels, which need at least " + std::to_string(minimum) +
                                   " bytes of coded data, but the file has " + std::to_string(file_size) +
                                   " bytes (truncated or corrupt)");
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
    const Format format = format_of(bytes);
    if (format == Format::unsupported) {
        throw InputError(path, "is a GIF, PSD, PIC or PNM file; only PNG, JPEG, BMP and TGA are read");
    }
    if (format == Format::tga && lowercase_extension(path) != ".tga") {
        // TGA has no signature: anything unrecognised would be tried as one.
        throw InputError(path, "not a valid PNG, JPEG or BMP file (no known signature)");
    }
    check_complete(bytes, format, path);
    // Check the size in the header before stb allocates anything.
    int width = 0, height = 0, channels = 0;
    if (stbi_info_from_memory(bytes.data(), length, &width, &height, &channels) == 0) {
        throw InputError(path, "not a valid PNG, JPEG, BMP or TGA file (" + stb_reason() + ")");
    }
    check_image_size(width, height, path);
    if (format == Format::jpeg) check_jpeg_data_size(bytes.size(), width, height, path);

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
