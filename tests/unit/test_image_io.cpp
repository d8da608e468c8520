// Image files: round trips in every format, orientation, EXR metadata, PNG exposure, atomic
// writes and check_image_writable. Malformed input is in test_image_io_errors.cpp.
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "image_files.hpp"

#include <catch2/catch.hpp>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfStringAttribute.h>
#include <ImfTiledOutputFile.h>
#include <half.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

using namespace freezeray;
using namespace freezeray::test;

namespace {

// A 7x3 image (not square, so a transposition shows) whose every channel of every pixel
// differs, with values in (0, 1] so that it survives the 8-bit formats too.
Image distinct_image() {
    Image image(7, 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 7; ++x) {
            image.at(x, y) = Spectrum((x + 1) / 8.0f, (y + 1) / 4.0f, (x + 7 * y + 1) / 22.0f);
        }
    }
    return image;
}

// The same image with values a float format must keep exactly: tiny, huge, zero, negative.
Image extreme_image() {
    Image image = distinct_image();
    image.at(0, 0) = Spectrum(1e-7f, 123456.78f, 0.0f);
    image.at(6, 2) = Spectrum(-0.5f, 3.0e38f, 1.0f / 3.0f);
    return image;
}

// Writes an EXR with the given channels (all stored as `stored_type`, from float planes that
// OpenEXR converts) through OpenEXR itself, to test files we did not write: half floats,
// unsigned integers, alpha, grey, other compressions, tiles, a data window away from the origin.
struct ExrLayout {
    Imf::PixelType stored_type = Imf::FLOAT;
    Imf::Compression compression = Imf::NO_COMPRESSION;
    int tile_size = 0;                               // 0: scan lines
    Imf::LevelMode levels = Imf::ONE_LEVEL;          // for tiles
    Imath::V2i origin = Imath::V2i(0, 0);            // the data window's top left corner
    Imf::LineOrder line_order = Imf::INCREASING_Y;
};

void write_exr_with_channels(const std::string& path, int width, int height, const std::vector<std::string>& names,
                             const std::vector<std::vector<float>>& planes, const ExrLayout& layout = {}) {
    const Imath::Box2i window(layout.origin, layout.origin + Imath::V2i(width - 1, height - 1));
    Imf::Header header(window, window, 1.0f, Imath::V2f(0.0f, 0.0f), 1.0f, layout.line_order, layout.compression);
    // OpenEXR writes from buffers of the stored type: the planes converted to half or uint.
    std::vector<std::vector<half>> halves;
    std::vector<std::vector<std::uint32_t>> integers;
    Imf::FrameBuffer frame;
    for (std::size_t i = 0; i < names.size(); ++i) {
        header.channels().insert(names[i], Imf::Channel(layout.stored_type));
        const void* buffer = planes[i].data();
        if (layout.stored_type == Imf::HALF) {
            buffer = halves.emplace_back(planes[i].begin(), planes[i].end()).data();
        } else if (layout.stored_type == Imf::UINT) {
            buffer = integers.emplace_back(planes[i].begin(), planes[i].end()).data();
        }
        frame.insert(names[i], Imf::Slice::Make(layout.stored_type, buffer, window));
    }
    if (layout.tile_size == 0) {
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(height);
        return;
    }
    header.setTileDescription(Imf::TileDescription(layout.tile_size, layout.tile_size, layout.levels));
    Imf::TiledOutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writeTiles(0, file.numXTiles(0) - 1, 0, file.numYTiles(0) - 1);  // the full-resolution level
    // The smaller levels of a mipmap, each from the same planes: only their presence matters here.
    for (int level = 1; level < file.numLevels(); ++level) {
        file.writeTiles(0, file.numXTiles(level) - 1, 0, file.numYTiles(level) - 1, level);
    }
}

// The bits of a float, to compare values exactly (-0 and 0 differ, a NaN equals itself).
std::uint32_t bits_of(float value) { return std::bit_cast<std::uint32_t>(value); }

}  // namespace

TEST_CASE("image_format_for_path picks the format from the extension in any case", "[unit][image]") {
    CHECK(image_format_for_path("out.exr") == ImageFormat::Exr);
    CHECK(image_format_for_path("some/folder/out.PFM") == ImageFormat::Pfm);
    CHECK(image_format_for_path("out.Hdr") == ImageFormat::Hdr);
    CHECK(image_format_for_path("a.b.png") == ImageFormat::Png);
    for (const std::string path : {"out.jpg", "out.txt", "out", "out.exr.bak", "folder.exr/out"}) {
        CHECK_THAT(input_error_message([&] { image_format_for_path(path); }), Catch::Contains(path));
    }
}

TEST_CASE("the sRGB transfer function follows IEC 61966-2-1", "[unit][image]") {
    CHECK(linear_to_srgb(0.0f) == 0.0f);
    CHECK(linear_to_srgb(1.0f) == Approx(1.0f).margin(1e-6));
    CHECK(linear_to_srgb(0.001f) == Approx(0.01292f));               // the linear segment
    CHECK(linear_to_srgb(0.214041f) == Approx(0.5f).margin(1e-5));   // 1.055 * 0.214041^(1/2.4) - 0.055
    CHECK(srgb_to_linear(0.5f) == Approx(0.214041f).margin(1e-6));   // ((0.5 + 0.055) / 1.055)^2.4
    CHECK(srgb_to_linear(0.04045f) == Approx(0.0031308f).margin(1e-6));  // the two pieces meet here
    for (int i = 0; i <= 100; ++i) {
        const float linear = i / 100.0f;
        CHECK(srgb_to_linear(linear_to_srgb(linear)) == Approx(linear).margin(1e-6));
    }
}

TEST_CASE("EXR and PFM round trips are exact", "[unit][image]") {
    TemporaryFolder folder;
    const Image original = extreme_image();
    for (const std::string name : {"exact.exr", "exact.pfm", "UPPER.EXR"}) {
        INFO(name);
        write_image(folder.file(name), original);
        const Image read = read_image(folder.file(name));
        REQUIRE(read.width() == 7);
        REQUIRE(read.height() == 3);
        for (int y = 0; y < 3; ++y) {
            for (int x = 0; x < 7; ++x) {
                INFO("pixel " << x << ", " << y);
                for (int c = 0; c < 3; ++c) CHECK(read.at(x, y)[c] == original.at(x, y)[c]);
            }
        }
    }
}

TEST_CASE("HDR round trips within RGBE precision", "[unit][image]") {
    TemporaryFolder folder;
    Image original = distinct_image();
    original.at(3, 1) = Spectrum(5000.0f, 20.0f, 0.001f);  // RGBE shares one exponent per pixel
    write_image(folder.file("rgbe.hdr"), original);
    const Image read = read_image(folder.file("rgbe.hdr"));
    REQUIRE(read.width() == 7);
    REQUIRE(read.height() == 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 7; ++x) {
            // 8-bit mantissas relative to the largest channel: under 1 % of it.
            const float tolerance = 0.01f * max_component(original.at(x, y));
            for (int c = 0; c < 3; ++c) CHECK(std::abs(read.at(x, y)[c] - original.at(x, y)[c]) <= tolerance);
        }
    }
}

TEST_CASE("the HDR reader decodes RGBE as Radiance does, flat or run-length encoded", "[unit][image]") {
    TemporaryFolder folder;
    // One flat pixel: mantissas 128, 64, 0 and exponent 129 mean (m + 0.5) * 2^(129 - 136):
    // 128.5 / 128 = 1.00390625, 64.5 / 128 = 0.50390625, and a zero mantissa stays 0.
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n";
    std::vector<unsigned char> bytes(header.begin(), header.end());
    for (unsigned char value : {128, 64, 0, 129}) bytes.push_back(value);
    write_bytes(folder.file("flat.hdr"), bytes);
    CHECK(read_image(folder.file("flat.hdr")).at(0, 0) == Spectrum(1.00390625f, 0.50390625f, 0.0f));

    // An 8-pixel scanline in run-length encoding: the 2, 2, width marker, then per channel a run
    // (128 + count, value) or a literal stretch (count, values).
    const std::string wide = "#?RADIANCE\n\n-Y 1 +X 8\n";
    bytes.assign(wide.begin(), wide.end());
    for (unsigned char value : {2, 2, 0, 8,                       // marker, width 8
                                128 + 8, 128,                     // R: 128 eight times
                                4, 0, 64, 0, 64, 128 + 4, 0,      // G: 0, 64, 0, 64, then 0 four times
                                128 + 8, 0,                       // B: 0 eight times
                                128 + 8, 129}) {                  // E: 129 eight times
        bytes.push_back(value);
    }
    write_bytes(folder.file("encoded.hdr"), bytes);
    const Image encoded = read_image(folder.file("encoded.hdr"));
    REQUIRE(encoded.width() == 8);
    CHECK(encoded.at(0, 0) == Spectrum(1.00390625f, 0.0f, 0.0f));
    CHECK(encoded.at(1, 0) == Spectrum(1.00390625f, 0.50390625f, 0.0f));
    CHECK(encoded.at(7, 0) == Spectrum(1.00390625f, 0.0f, 0.0f));
}

TEST_CASE("PNG round trips within 8-bit sRGB quantisation", "[unit][image]") {
    TemporaryFolder folder;
    const Image original = distinct_image();
    write_image(folder.file("eight_bit.png"), original);
    const Image read = read_image(folder.file("eight_bit.png"));
    REQUIRE(read.width() == 7);
    REQUIRE(read.height() == 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 7; ++x) {
            for (int c = 0; c < 3; ++c) {
                // Rounding to the nearest of 255 steps in the encoded (sRGB) domain.
                const float encoded_error = linear_to_srgb(read.at(x, y)[c]) - linear_to_srgb(original.at(x, y)[c]);
                CHECK(std::abs(encoded_error) <= 0.5f / 255.0f + 1e-5f);
            }
        }
    }
}

TEST_CASE("every format keeps the top row at the top and the left column at the left", "[unit][image]") {
    TemporaryFolder folder;
    Image original(5, 2, Spectrum(0.0f));
    original.at(0, 0) = Spectrum(1.0f, 0.0f, 0.0f);  // top left: red
    original.at(4, 0) = Spectrum(0.0f, 1.0f, 0.0f);  // top right: green
    original.at(0, 1) = Spectrum(0.0f, 0.0f, 1.0f);  // bottom left: blue
    for (const std::string name : {"top.exr", "top.pfm", "top.hdr", "top.png"}) {
        INFO(name);
        write_image(folder.file(name), original);
        const Image read = read_image(folder.file(name));
        REQUIRE(read.width() == 5);
        REQUIRE(read.height() == 2);
        CHECK(read.at(0, 0).x == Approx(1.0f).margin(0.01));
        CHECK(read.at(4, 0).y == Approx(1.0f).margin(0.01));
        CHECK(read.at(0, 1).z == Approx(1.0f).margin(0.01));
        CHECK(read.at(4, 1).x + read.at(4, 1).y + read.at(4, 1).z == Approx(0.0f).margin(0.01));
    }
}

TEST_CASE("PFM files are written bottom row first, little endian, with scale -1", "[unit][image]") {
    TemporaryFolder folder;
    Image original(1, 2);
    original.at(0, 0) = Spectrum(1.0f, 2.0f, 3.0f);  // top
    original.at(0, 1) = Spectrum(4.0f, 5.0f, 6.0f);  // bottom
    write_image(folder.file("layout.pfm"), original);
    const std::string header = "PF\n1 2\n-1\n";
    const std::vector<unsigned char> bytes = read_bytes(folder.file("layout.pfm"));
    REQUIRE(bytes.size() == header.size() + 6 * 4);
    CHECK(std::string(bytes.begin(), bytes.begin() + static_cast<long>(header.size())) == header);
    const std::vector<unsigned char> first_float(bytes.begin() + static_cast<long>(header.size()),
                                                 bytes.begin() + static_cast<long>(header.size()) + 4);
    CHECK(first_float == little_endian_bytes(4.0f));  // the bottom row's red comes first
}

TEST_CASE("the PFM reader takes big-endian, grey and scaled files", "[unit][image]") {
    TemporaryFolder folder;
    SECTION("big endian RGB (positive scale)") {
        write_file(folder.file("big.pfm"), "PF\n2 1\n1.0\n", {1.5f, 2.5f, 3.5f, -4.0f, 0.0f, 8.0f}, false);
        const Image image = read_image(folder.file("big.pfm"));
        REQUIRE(image.width() == 2);
        REQUIRE(image.height() == 1);
        CHECK(image.at(0, 0) == Spectrum(1.5f, 2.5f, 3.5f));
        CHECK(image.at(1, 0) == Spectrum(-4.0f, 0.0f, 8.0f));
    }
    SECTION("grey, bottom row first, with Windows line endings") {
        write_file(folder.file("grey.pfm"), "Pf\r\n1 2\r\n-1.0\r\n", {0.25f, 0.75f});
        const Image image = read_image(folder.file("grey.pfm"));
        REQUIRE(image.width() == 1);
        REQUIRE(image.height() == 2);
        CHECK(image.at(0, 0) == Spectrum(0.75f));
        CHECK(image.at(0, 1) == Spectrum(0.25f));
    }
    SECTION("a scale of magnitude 2 multiplies the values, as in pbrt") {
        write_file(folder.file("scaled.pfm"), "PF\n1 1\n-2.0\n", {1.0f, 2.0f, 3.0f});
        CHECK(read_image(folder.file("scaled.pfm")).at(0, 0) == Spectrum(2.0f, 4.0f, 6.0f));
    }
}

TEST_CASE("EXR files keep the image metadata as string attributes", "[unit][image]") {
    TemporaryFolder folder;
    Image original = distinct_image();
    original.metadata = {{"spp", "64"}, {"integrator", "path"}, {"seed", "7"},
                         {"note", "spaces, punctuation; and \xc3\xbcnicode"}, {"empty", ""}};
    write_image(folder.file("metadata.exr"), original);
    CHECK(read_image(folder.file("metadata.exr")).metadata == original.metadata);

    Image reserved = distinct_image();
    reserved.metadata = {{"channels", "would corrupt the header"}};
    CHECK_THAT(input_error_message([&] { write_image(folder.file("reserved.exr"), reserved); }),
               Catch::Contains("reserved.exr"));
}

TEST_CASE("the EXR reader takes half floats, ignores alpha, and reads Y as grey", "[unit][image]") {
    TemporaryFolder folder;
    // 2x1 image; values exactly representable in half precision.
    write_exr_with_channels(folder.file("half.exr"), 2, 1, {"A", "B", "G", "R"},
                            {{1.0f, 0.5f}, {0.25f, 4.0f}, {0.5f, 2.0f}, {0.75f, 1024.0f}}, {.stored_type = Imf::HALF});
    const Image half = read_image(folder.file("half.exr"));
    REQUIRE(half.width() == 2);
    CHECK(half.at(0, 0) == Spectrum(0.75f, 0.5f, 0.25f));
    CHECK(half.at(1, 0) == Spectrum(1024.0f, 2.0f, 4.0f));

    write_exr_with_channels(folder.file("grey.exr"), 1, 2, {"Y"}, {{0.125f, 3.0f}});
    const Image grey = read_image(folder.file("grey.exr"));
    REQUIRE(grey.height() == 2);
    CHECK(grey.at(0, 0) == Spectrum(0.125f));
    CHECK(grey.at(0, 1) == Spectrum(3.0f));

    // OpenEXR keeps the channel list in alphabetical order, so the message lists W before Z.
    write_exr_with_channels(folder.file("depth.exr"), 1, 1, {"Z", "W"}, {{1.0f}, {2.0f}});
    CHECK_THAT(input_error_message([&] { read_image(folder.file("depth.exr")); }),
               Catch::Contains("depth.exr") && Catch::Contains("W, Z"));
}

TEST_CASE("an EXR round trip is bit-exact, as 32-bit float B, G, R with ZIP, and keeps the freezeray:* attributes",
          "[unit][image]") {
    TemporaryFolder folder;
    Image original = extreme_image();
    // Values that == cannot tell apart or that never equal themselves: every bit must survive.
    original.at(1, 0) = Spectrum(-0.0f, std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::infinity());
    original.at(2, 0) = Spectrum(-std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                                 std::numeric_limits<float>::max());
    original.metadata = {{"freezeray:scene", "scenes/cornell-box/scene.json"}, {"freezeray:integrator", "pt-mis"},
                         {"freezeray:samples_per_pixel", "1024"}, {"freezeray:seed", "7"},
                         {"freezeray:seconds", "12.5"}, {"freezeray:estimated_relative_mse", "0.00042"}};
    const std::string path = folder.file("exact.exr");
    write_image(path, original);

    const Image read = read_image(path);
    REQUIRE(read.width() == original.width());
    REQUIRE(read.height() == original.height());
    for (std::size_t i = 0; i < original.pixel_count(); ++i) {
        INFO("pixel " << i);
        for (int c = 0; c < 3; ++c) CHECK(bits_of(read[i][c]) == bits_of(original[i][c]));
    }
    CHECK(read.metadata == original.metadata);

    // What is in the file, as OpenEXR itself reads it.
    Imf::InputFile file(path.c_str());
    CHECK(file.header().compression() == Imf::ZIP_COMPRESSION);
    std::vector<std::string> channels;
    for (auto channel = file.header().channels().begin(); channel != file.header().channels().end(); ++channel) {
        channels.push_back(channel.name());
        CHECK(channel.channel().type == Imf::FLOAT);
    }
    CHECK(channels == std::vector<std::string>{"B", "G", "R"});
    const auto* spp = file.header().findTypedAttribute<Imf::StringAttribute>("freezeray:samples_per_pixel");
    REQUIRE(spp != nullptr);
    CHECK(spp->value() == "1024");
}

TEST_CASE("the EXR reader takes every lossless compression, tiles, mipmaps, uint, an offset window, bottom-up rows",
          "[unit][image]") {
    TemporaryFolder folder;
    // A 37x21 image (more than one block of 16 or 32 rows, tiles clipped at the edges) whose
    // values are whole numbers, exact in half precision and as unsigned integers.
    const int width = 37, height = 21;
    std::vector<std::vector<float>> planes(3, std::vector<float>(width * height));
    for (int i = 0; i < width * height; ++i) {
        planes[0][static_cast<std::size_t>(i)] = static_cast<float>(i % 97);
        planes[1][static_cast<std::size_t>(i)] = static_cast<float>((i * 7) % 13);
        planes[2][static_cast<std::size_t>(i)] = static_cast<float>(i / width);
    }
    struct Case {
        const char* name;
        ExrLayout layout;
    };
    const Case cases[] = {
        {"none.exr", {}},
        {"rle.exr", {.compression = Imf::RLE_COMPRESSION}},
        {"zips.exr", {.compression = Imf::ZIPS_COMPRESSION}},
        {"zip.exr", {.compression = Imf::ZIP_COMPRESSION}},
        {"piz.exr", {.compression = Imf::PIZ_COMPRESSION}},
        {"pxr24-half.exr", {.stored_type = Imf::HALF, .compression = Imf::PXR24_COMPRESSION}},  // lossless on half
        {"uint.exr", {.stored_type = Imf::UINT, .compression = Imf::ZIP_COMPRESSION}},
        {"tiled.exr", {.compression = Imf::ZIP_COMPRESSION, .tile_size = 8}},
        {"mipmap.exr", {.stored_type = Imf::HALF, .compression = Imf::PIZ_COMPRESSION, .tile_size = 16,
                        .levels = Imf::MIPMAP_LEVELS}},
        {"big-tiles.exr", {.tile_size = 64}},  // one tile larger than the image
        {"offset.exr", {.compression = Imf::ZIP_COMPRESSION, .origin = Imath::V2i(-5, 1000)}},
        {"bottom-up.exr", {.compression = Imf::PIZ_COMPRESSION, .line_order = Imf::DECREASING_Y}},
    };
    for (const Case& test : cases) {
        INFO(test.name);
        write_exr_with_channels(folder.file(test.name), width, height, {"R", "G", "B"}, planes, test.layout);
        const Image read = read_image(folder.file(test.name));
        REQUIRE(read.width() == width);
        REQUIRE(read.height() == height);
        int wrong = 0;
        for (std::size_t i = 0; i < read.pixel_count(); ++i) {
            for (int c = 0; c < 3; ++c) wrong += read[i][c] != planes[static_cast<std::size_t>(c)][i];
        }
        CHECK(wrong == 0);
    }
}

TEST_CASE("EXR tiles too large for their image are refused before OpenEXR allocates them", "[unit][image]") {
    TemporaryFolder folder;
    // A 4x4 file in one tile of 64 x 64 is read (a tile larger than the image is legal) ...
    write_exr_with_channels(folder.file("tiled.exr"), 4, 4, {"Y"}, {std::vector<float>(16, 2.0f)}, {.tile_size = 64});
    CHECK(read_image(folder.file("tiled.exr")).at(3, 3) == Spectrum(2.0f));
    // ... but with tiles of 60000 x 60000, OpenEXR would allocate 14 GB for one row of them.
    std::vector<unsigned char> bytes = read_bytes(folder.file("tiled.exr"));
    const std::size_t tiles = exr_attribute_value(bytes, "tiles", "tiledesc");
    put_little_endian(bytes, tiles, 60000);
    put_little_endian(bytes, tiles + 4, 60000);
    write_bytes(folder.file("huge-tiles.exr"), bytes);
    CHECK_THAT(input_error_message([&] { read_image(folder.file("huge-tiles.exr")); }),
               Catch::Contains(folder.file("huge-tiles.exr")) && Catch::Contains("too large"));
}

TEST_CASE("an uncompressed EXR block shorter than its pixels is refused", "[unit][image]") {
    // OpenEXR 3.1 would take the short block's data as its pixels and fill the rest from its
    // buffer. Found by fuzz_image for scan lines (the input without its selector byte) ...
    TemporaryFolder folder;
    std::vector<unsigned char> bytes =
        read_bytes(std::string(FREEZERAY_SOURCE_DIR) + "/tests/fuzz/regressions/image/exr-uint-chunk-too-short.bin");
    bytes.erase(bytes.begin());
    write_bytes(folder.file("short-line.exr"), bytes);
    CHECK_THAT(input_error_message([&] { read_image(folder.file("short-line.exr")); }),
               Catch::Contains(folder.file("short-line.exr")) && Catch::Contains("uncompressed OpenEXR scan line"));

    // ... and made here for tiles: the first tile's data size, 4 bytes short.
    write_exr_with_channels(folder.file("short-tile.exr"), 4, 4, {"Y"}, {std::vector<float>(16, 1.0f)}, {.tile_size = 2});
    REQUIRE(read_image(folder.file("short-tile.exr")).at(3, 3) == Spectrum(1.0f));
    bytes = read_bytes(folder.file("short-tile.exr"));
    const std::size_t table = exr_header_end(bytes);
    const std::size_t first_tile = bytes[table] | (std::size_t(bytes[table + 1]) << 8);  // the first table entry
    // A tile chunk: tile x, tile y, level x, level y, data size, data (2 x 2 floats, 16 bytes).
    REQUIRE(bytes[first_tile + 16] == 16);
    bytes[first_tile + 16] = 12;
    write_bytes(folder.file("short-tile.exr"), bytes);
    CHECK_THAT(input_error_message([&] { read_image(folder.file("short-tile.exr")); }),
               Catch::Contains(folder.file("short-tile.exr")) && Catch::Contains("uncompressed OpenEXR tile (0, 0)"));
}

TEST_CASE("multi-part and subsampled EXR files are refused with the reason", "[unit][image]") {
    TemporaryFolder folder;
    const std::vector<float> plane(16, 1.0f);

    Imf::Header part(4, 4);
    part.channels().insert("Y", Imf::Channel(Imf::FLOAT));
    part.setName("one");
    part.setType(Imf::SCANLINEIMAGE);
    Imf::Header other = part;
    other.setName("two");
    const Imf::Header parts[] = {part, other};
    {
        Imf::MultiPartOutputFile file(folder.file("parts.exr").c_str(), parts, 2);
        for (int p = 0; p < 2; ++p) {
            Imf::OutputPart output(file, p);
            Imf::FrameBuffer frame;
            frame.insert("Y", Imf::Slice::Make(Imf::FLOAT, plane.data(), part.dataWindow()));
            output.setFrameBuffer(frame);
            output.writePixels(4);
        }
    }
    CHECK_THAT(input_error_message([&] { read_image(folder.file("parts.exr")); }),
               Catch::Contains(folder.file("parts.exr")) && Catch::Contains("multi-part"));

    // Chroma channels at half resolution, as in OpenEXR's luminance/chroma images.
    Imf::Header header(4, 4);
    header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
    header.channels().insert("BY", Imf::Channel(Imf::FLOAT, 2, 2));
    {
        const std::vector<float> chroma(4, 0.5f);
        Imf::OutputFile file(folder.file("chroma.exr").c_str(), header);
        Imf::FrameBuffer frame;
        frame.insert("Y", Imf::Slice::Make(Imf::FLOAT, plane.data(), header.dataWindow()));
        frame.insert("BY", Imf::Slice::Make(Imf::FLOAT, chroma.data(), header.dataWindow(), 0, 0, 2, 2));
        file.setFrameBuffer(frame);
        file.writePixels(4);
    }
    CHECK_THAT(input_error_message([&] { read_image(folder.file("chroma.exr")); }),
               Catch::Contains(folder.file("chroma.exr")) && Catch::Contains("'BY' is subsampled"));
}

TEST_CASE("PNG exposure scales by 2^stops before encoding; float formats ignore it", "[unit][image]") {
    TemporaryFolder folder;
    Image original(3, 1);
    original.at(0, 0) = Spectrum(0.25f);
    original.at(1, 0) = Spectrum(4.0f, -1.0f, std::nanf(""));  // clamped: white, black, black
    original.at(2, 0) = Spectrum(0.05f);

    write_image(folder.file("brighter.png"), original, ImageWriteOptions{1.0f});
    const Image brighter = read_image(folder.file("brighter.png"));
    CHECK(brighter.at(0, 0).x == Approx(0.5f).epsilon(0.01));
    CHECK(brighter.at(1, 0) == Spectrum(1.0f, 0.0f, 0.0f));
    CHECK(brighter.at(2, 0).x == Approx(0.1f).epsilon(0.02));

    write_image(folder.file("darker.png"), original, ImageWriteOptions{-2.0f});
    CHECK(read_image(folder.file("darker.png")).at(0, 0).x == Approx(0.0625f).epsilon(0.02));

    write_image(folder.file("float.exr"), original, ImageWriteOptions{3.0f});
    CHECK(read_image(folder.file("float.exr")).at(0, 0) == Spectrum(0.25f));
}

TEST_CASE("writing over an existing image replaces it and leaves no temporary file", "[unit][image]") {
    TemporaryFolder folder;
    for (const std::string name : {"over.exr", "over.pfm", "over.hdr", "over.png"}) {
        INFO(name);
        write_image(folder.file(name), Image(4, 4, Spectrum(0.1f)));
        write_image(folder.file(name), Image(2, 3, Spectrum(0.5f)));
        const Image read = read_image(folder.file(name));
        CHECK(read.width() == 2);
        CHECK(read.height() == 3);
        CHECK(read.at(1, 2).x == Approx(0.5f).epsilon(0.01));
    }
    CHECK(folder.entries() == std::vector<std::string>{"over.exr", "over.hdr", "over.pfm", "over.png"});
}

TEST_CASE("a failed write throws InputError naming the file and leaves nothing behind", "[unit][image]") {
    TemporaryFolder folder;
    const Image image = distinct_image();

    const std::string in_missing_folder = folder.file("missing/out.exr");
    CHECK_THAT(input_error_message([&] { write_image(in_missing_folder, image); }),
               Catch::Contains(in_missing_folder) && Catch::Contains("does not exist"));

    // A folder where the file should go: the rename must fail, after the temporary file was written.
    std::filesystem::create_directory(folder.file("taken.pfm"));
    CHECK_THAT(input_error_message([&] { write_image(folder.file("taken.pfm"), image); }),
               Catch::Contains("taken.pfm"));

    CHECK_THAT(input_error_message([&] { write_image(folder.file("empty.exr"), Image()); }),
               Catch::Contains("empty.exr"));
    CHECK_THAT(input_error_message([&] { write_image(folder.file("unknown.tiff"), image); }),
               Catch::Contains("unknown.tiff"));

    CHECK(folder.entries() == std::vector<std::string>{"taken.pfm"});
    CHECK(std::filesystem::is_empty(folder.file("taken.pfm")));
}

TEST_CASE("check_image_writable accepts a writable path and refuses the rest", "[unit][image]") {
    TemporaryFolder folder;
    check_image_writable(folder.file("fine.exr"));
    check_image_writable(folder.file("FINE.PNG"));
    CHECK(folder.entries().empty());  // the probe file is gone

    write_file(folder.file("a_file"), "not a folder");
    std::filesystem::create_directory(folder.file("a_folder.exr"));
    for (const std::string& path : {folder.file("missing/out.exr"), folder.file("a_file/out.exr"),
                                    folder.file("out.gif"), folder.file("a_folder.exr")}) {
        CHECK_THAT(input_error_message([&] { check_image_writable(path); }), Catch::Contains(path));
    }
}
