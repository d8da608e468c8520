// The portable float map (PFM), read and written by our own code. The format, as described at
// https://netpbm.sourceforge.net/doc/pfm.html (and by Paul Debevec, who introduced it):
//
//     PF            "PF" for RGB, "Pf" for a single grey channel
//     7 3           width and height in pixels
//     -1.0          scale: its sign gives the byte order (negative = little endian)
//     <floats>      32-bit IEEE floats, rows from the BOTTOM of the image to the top
//
// The header tokens are separated by white space, and exactly one white space character ends
// the scale. A reader must not trust any of it: every field is checked against the file length.
#include "freezeray/error.hpp"
#include "image_io_formats.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace freezeray::image_io {

namespace {

bool is_white_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Walks through the header of a PFM file, one token at a time.
class HeaderReader {
public:
    HeaderReader(const Bytes& bytes, const std::string& path) : bytes_(bytes), path_(path) {}

    // The next white-space separated word; `what` names it in the error when the header ends.
    std::string_view next_token(const char* what) {
        while (position_ < bytes_.size() && is_white_space(bytes_[position_])) ++position_;
        const std::size_t start = position_;
        // A header word is short; stop early on garbage so the message stays readable.
        while (position_ < bytes_.size() && !is_white_space(bytes_[position_]) && position_ - start < 32) ++position_;
        if (position_ == start) {
            fail(std::string("the header ends before the ") + what);
        }
        return {reinterpret_cast<const char*>(bytes_.data()) + start, position_ - start};
    }

    // Reads a positive whole number such as the width.
    std::int64_t next_integer(const char* what) {
        const std::string_view token = next_token(what);
        std::int64_t value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size()) {
            fail(std::string("the ") + what + " '" + std::string(token) + "' is not a whole number");
        }
        return value;
    }

    // Reads the scale, which must be a finite, non-zero number.
    float next_scale() {
        const std::string_view token = next_token("scale");
        float value = 0.0f;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value) || value == 0.0f) {
            fail("the scale '" + std::string(token) + "' is not a finite, non-zero number");
        }
        return value;
    }

    // Skips the single white space character that ends the header ("\r\n" counts as one, for
    // files written on Windows in text mode).
    void end_of_header() {
        if (position_ >= bytes_.size()) {
            fail("the file ends right after the header, with no pixel data");
        }
        const unsigned char last = bytes_[position_++];
        if (last == '\r' && position_ < bytes_.size() && bytes_[position_] == '\n') ++position_;
    }

    std::size_t position() const { return position_; }

    [[noreturn]] void fail(const std::string& reason) const {
        throw InputError(path_, "not a valid PFM file: " + reason);
    }

private:
    const Bytes& bytes_;
    const std::string& path_;
    std::size_t position_ = 2;  // after the "PF" magic
};

// The float stored in four bytes in the given byte order.
float float_from_bytes(const unsigned char* bytes, bool little_endian) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) {
        const int byte = little_endian ? 3 - i : i;  // most significant byte first
        bits = (bits << 8) | bytes[byte];
    }
    return std::bit_cast<float>(bits);
}

// Appends a float as four little-endian bytes, whatever the byte order of this machine.
void append_little_endian(Bytes& bytes, float value) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    for (int shift = 0; shift < 32; shift += 8) {
        bytes.push_back(static_cast<unsigned char>(bits >> shift));
    }
}

}  // namespace

// Decodes a PFM file (RGB or grey, either byte order) into an image with row 0 at the top.
Image decode_pfm(const Bytes& bytes, const std::string& path) {
    HeaderReader header(bytes, path);
    if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f')) {
        header.fail("it does not start with \"PF\" or \"Pf\"");
    }
    const int channels = bytes[1] == 'F' ? 3 : 1;
    if (bytes.size() > 2 && !is_white_space(bytes[2])) {
        header.fail("the \"PF\" magic is not followed by white space");
    }
    const std::int64_t width = header.next_integer("width");
    const std::int64_t height = header.next_integer("height");
    check_image_size(width, height, path);
    const float scale = header.next_scale();
    header.end_of_header();

    // Both sizes are at most 2^28 * 12 bytes, so this arithmetic cannot overflow.
    const std::uint64_t expected = static_cast<std::uint64_t>(width * height * channels) * 4;
    const std::uint64_t found = bytes.size() - header.position();
    if (found < expected) {
        header.fail("truncated: a " + std::to_string(width) + "x" + std::to_string(height) + " image needs " +
                    std::to_string(expected) + " bytes of pixel data but only " + std::to_string(found) +
                    " follow the header");
    }
    if (found > expected) {
        header.fail(std::to_string(found - expected) + " unexpected bytes after the pixel data");
    }

    // Like pbrt-v3's ReadImagePFM (Pharr, Jakob and Humphreys, src/core/imageio.cpp), pixel values
    // are multiplied by |scale| when it is not 1.
    const bool little_endian = scale < 0.0f;
    const float multiplier = std::abs(scale);
    Image image(static_cast<int>(width), static_cast<int>(height));
    const unsigned char* data = bytes.data() + header.position();
    for (int row = 0; row < image.height(); ++row) {
        const int y = image.height() - 1 - row;  // the file starts with the bottom row
        for (int x = 0; x < image.width(); ++x) {
            Spectrum& pixel = image.at(x, y);
            for (int c = 0; c < 3; ++c) {
                const int channel = channels == 3 ? c : 0;
                const float value = float_from_bytes(data + 4 * channel, little_endian);
                pixel[c] = multiplier == 1.0f ? value : value * multiplier;
            }
            data += 4 * channels;
        }
    }
    return image;
}

// Encodes an image as a little-endian RGB PFM with scale -1.
Bytes encode_pfm(const Image& image) {
    const std::string header = "PF\n" + std::to_string(image.width()) + " " + std::to_string(image.height()) + "\n-1\n";
    Bytes bytes(header.begin(), header.end());
    bytes.reserve(header.size() + image.pixel_count() * 12);
    for (int y = image.height() - 1; y >= 0; --y) {  // bottom row first
        for (int x = 0; x < image.width(); ++x) {
            const Spectrum& pixel = image.at(x, y);
            for (int c = 0; c < 3; ++c) append_little_endian(bytes, pixel[c]);
        }
    }
    return bytes;
}

}  // namespace freezeray::image_io
