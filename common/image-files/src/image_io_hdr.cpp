// Radiance HDR (RGBE) files: Greg Ward, "Real Pixels", Graphics Gems II, 1991, and the Radiance
// file format notes (https://radsite.lbl.gov/radiance/refer/filefmts.pdf). A file is
//
//     #?RADIANCE               text header lines, ended by an empty line
//     FORMAT=32-bit_rle_rgbe
//
//     -Y 3 +X 7                the resolution: rows from the top, pixels from the left
//     <scanlines>              4 bytes per pixel: mantissas R, G, B and a shared exponent E,
//                              each scanline flat or run-length encoded channel by channel
//
// We write with stb_image_write. We read with our own code: the stb_image in Debian 12 loops
// forever on a truncated or corrupt run-length scanline, and every count here is checked.
#include "freezeray/error.hpp"
#include "image_io_formats.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace freezeray::image_io {

namespace {

// Reads a Radiance file front to back, refusing to step past its end.
class RadianceReader {
public:
    RadianceReader(const Bytes& bytes, const std::string& path) : bytes_(bytes), path_(path) {}

    // The next text line without its newline; fails if the file ends first.
    std::string_view line() {
        const char* begin = reinterpret_cast<const char*>(bytes_.data()) + position_;
        const char* end = reinterpret_cast<const char*>(bytes_.data()) + bytes_.size();
        const char* newline = std::find(begin, end, '\n');
        if (newline == end) fail("the header ends without the resolution line");
        position_ += static_cast<std::size_t>(newline - begin) + 1;
        return {begin, static_cast<std::size_t>(newline - begin)};
    }

    // The next `count` bytes; fails with "truncated" if fewer remain.
    const unsigned char* take(std::size_t count) {
        if (bytes_.size() - position_ < count) fail("truncated: the pixel data ends early");
        const unsigned char* start = bytes_.data() + position_;
        position_ += count;
        return start;
    }

    // True when the next bytes start a run-length encoded scanline of `width` pixels: 2, 2,
    // then the width in two bytes (a flat pixel cannot start like this, as one of its
    // mantissas would be at least 128).
    bool at_encoded_scanline(int width) const {
        if (bytes_.size() - position_ < 4) return false;
        const unsigned char* next = bytes_.data() + position_;
        return next[0] == 2 && next[1] == 2 && (next[2] & 0x80) == 0 && ((next[2] << 8) | next[3]) == width;
    }

    std::size_t remaining() const { return bytes_.size() - position_; }

    [[noreturn]] void fail(const std::string& reason) const {
        throw InputError(path_, "not a valid Radiance HDR file: " + reason);
    }

private:
    const Bytes& bytes_;
    const std::string& path_;
    std::size_t position_ = 0;
};

// Parses a whole number from the resolution line, or fails.
int parse_size(std::string_view text, const RadianceReader& reader) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) {
        reader.fail("the size '" + std::string(text) + "' is not a whole number");
    }
    return value;
}

// One scanline in run-length encoding: for each of the 4 bytes of a pixel in turn, runs
// (a count above 128, then one value repeated count - 128 times) and literal stretches (a count
// of 1 to 128, then that many values).
void read_encoded_scanline(RadianceReader& reader, std::vector<unsigned char>& rgbe, int width) {
    reader.take(4);  // the 2, 2, width marker, already checked
    for (int component = 0; component < 4; ++component) {
        int x = 0;
        while (x < width) {
            int count = *reader.take(1);
            const bool run = count > 128;
            if (run) count -= 128;
            if (count == 0 || count > width - x) reader.fail("a run-length count is out of range");
            if (run) {
                const unsigned char value = *reader.take(1);
                for (int i = 0; i < count; ++i) rgbe[4 * (x++) + component] = value;
            } else {
                const unsigned char* values = reader.take(static_cast<std::size_t>(count));
                for (int i = 0; i < count; ++i) rgbe[4 * (x++) + component] = values[i];
            }
        }
    }
}

// The channel value of an RGBE mantissa: the centre of its quantisation step, as Radiance's
// colr_color does (Ward 1991), except that a zero mantissa stays exactly black.
float rgbe_channel(unsigned char mantissa, unsigned char exponent) {
    if (mantissa == 0 || exponent == 0) return 0.0f;
    return std::ldexp(mantissa + 0.5f, exponent - (128 + 8));
}

// stb_image_write hands us the encoded file in pieces; we append them to a byte vector.
void append_to_bytes(void* context, void* data, int size) {
    auto* bytes = static_cast<Bytes*>(context);
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes->insert(bytes->end(), begin, begin + size);
}

// A value RGBE can store: RGBE has no sign, NaN or infinity, and its exponent tops out near
// 2^127, so negatives and NaN become 0 and huge values are clamped.
float storable_in_rgbe(float value) {
    if (!(value > 0.0f)) return 0.0f;  // also catches NaN
    return std::min(value, 1e38f);
}

}  // namespace

// Decodes a Radiance RGBE file in the standard orientation (-Y H +X W) into linear floats.
Image decode_hdr(const Bytes& bytes, const std::string& path) {
    RadianceReader reader(bytes, path);
    if (bytes.size() < 2 || bytes[0] != '#' || bytes[1] != '?') {
        throw InputError(path, "not a Radiance HDR file (it does not start with \"#?\", as in \"#?RADIANCE\")");
    }
    // Header lines up to the first empty one. EXPOSURE lines are ignored, as stb_image and most
    // renderers do: our files store the radiance itself.
    for (std::string_view header = reader.line(); !header.empty(); header = reader.line()) {
        if (header.starts_with("FORMAT=") && header != "FORMAT=32-bit_rle_rgbe") {
            reader.fail("unsupported " + std::string(header) + " (only 32-bit_rle_rgbe is read)");
        }
    }
    // The resolution line, "-Y height +X width"; other orientations are rare and refused.
    const std::string_view resolution = reader.line();
    const std::size_t x_marker = resolution.find(" +X ");
    if (!resolution.starts_with("-Y ") || x_marker == std::string_view::npos) {
        reader.fail("unsupported resolution line '" + std::string(resolution) + "' (expected \"-Y height +X width\")");
    }
    const int height = parse_size(resolution.substr(3, x_marker - 3), reader);
    const int width = parse_size(resolution.substr(x_marker + 4), reader);
    check_image_size(width, height, path);
    // The fewest bytes that can hold the scanlines: run-length encoded, the 4-byte marker and,
    // for each component, runs of at most 127 pixels in 2 bytes; flat, 4 bytes a pixel. Checked
    // before allocating, so that a 60-byte file cannot claim gigabytes (found by fuzz_image).
    const bool may_be_encoded = width >= 8 && width <= 0x7fff;
    const std::uint64_t smallest_scanline = may_be_encoded ? 4 + 8 * ((std::uint64_t(width) + 126) / 127) : 4 * std::uint64_t(width);
    if (smallest_scanline * std::uint64_t(height) > reader.remaining()) {
        reader.fail("truncated: " + std::to_string(reader.remaining()) + " bytes cannot hold " + std::to_string(width) +
                    "x" + std::to_string(height) + " pixels");
    }

    Image image(width, height);
    std::vector<unsigned char> rgbe(static_cast<std::size_t>(width) * 4);
    for (int y = 0; y < height; ++y) {
        // Widths under 8 or over 32767 are always flat; otherwise each scanline says.
        if (width >= 8 && width <= 0x7fff && reader.at_encoded_scanline(width)) {
            read_encoded_scanline(reader, rgbe, width);
        } else {
            const unsigned char* flat = reader.take(rgbe.size());
            std::copy(flat, flat + rgbe.size(), rgbe.begin());
        }
        for (int x = 0; x < width; ++x) {
            const unsigned char* pixel = &rgbe[4 * static_cast<std::size_t>(x)];
            image.at(x, y) = Spectrum(rgbe_channel(pixel[0], pixel[3]), rgbe_channel(pixel[1], pixel[3]),
                                      rgbe_channel(pixel[2], pixel[3]));
        }
    }
    return image;
}

// Encodes linear radiance as a Radiance RGBE file (run-length encoded by stb_image_write).
Bytes encode_hdr(const Image& image, const std::string& path) {
    std::vector<float> values;
    values.reserve(image.pixel_count() * 3);
    for (const Spectrum& pixel : image.pixels()) {
        for (int c = 0; c < 3; ++c) values.push_back(storable_in_rgbe(pixel[c]));
    }
    Bytes bytes;
    if (stbi_write_hdr_to_func(append_to_bytes, &bytes, image.width(), image.height(), 3, values.data()) == 0) {
        throw InputError(path, "cannot encode the image as Radiance HDR");
    }
    return bytes;
}

}  // namespace freezeray::image_io
