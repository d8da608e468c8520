// Malformed image files: each must throw an InputError that names the file, and none may crash
// the reader or make it allocate absurd amounts of memory.
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "image_files.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <sys/resource.h>  // getrusage, for the memory a read takes

using namespace freezeray;
using namespace freezeray::test;
using Catch::Contains;

namespace {

// A 16x16 image with some variety, so that compressed formats have real content.
Image varied_image() {
    Image image(16, 16);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) image.at(x, y) = Spectrum(x / 15.0f, y / 15.0f, ((x * 7 + y * 3) % 11) / 10.0f);
    }
    return image;
}

// Reads `path`, accepting success or an InputError naming it: anything else fails the test.
void read_or_input_error(const std::string& path) {
    try {
        read_image(path);
    } catch (const InputError& error) {
        CHECK_THAT(error.what(), Contains(path));
    }
}

// Overwrites a big-endian 32-bit number in a byte vector.
void put_big_endian(std::vector<unsigned char>& bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<unsigned char>(value >> (24 - 8 * i));
}

}  // namespace

TEST_CASE("missing, empty and unnamed files throw InputError naming the file", "[unit][image]") {
    TemporaryFolder folder;
    const std::string missing = folder.file("missing.exr");
    CHECK_THAT(input_error_message([&] { read_image(missing); }), Contains(missing) && Contains("no such file"));

    std::filesystem::create_directory(folder.file("folder.png"));
    CHECK_THAT(input_error_message([&] { read_image(folder.file("folder.png")); }), Contains("folder.png"));

    write_file(folder.file("empty.pfm"), "");
    CHECK_THAT(input_error_message([&] { read_image(folder.file("empty.pfm")); }),
               Contains("empty.pfm") && Contains("empty"));

    for (const std::string name : {"image.txt", "image", "image.gif"}) {
        write_file(folder.file(name), "whatever");
        CHECK_THAT(input_error_message([&] { read_image(folder.file(name)); }), Contains(folder.file(name)));
    }
}

TEST_CASE("garbage bytes under an image extension throw InputError", "[unit][image]") {
    TemporaryFolder folder;
    std::string garbage;
    for (int i = 0; i < 40; ++i) garbage += "this is not an image at all; ";
    for (const std::string name : {"junk.exr", "junk.png", "junk.hdr", "junk.pfm", "junk.jpg", "junk.bmp", "junk.tga"}) {
        write_file(folder.file(name), garbage);
        CHECK_THAT(input_error_message([&] { read_image(folder.file(name)); }), Contains(folder.file(name)));
    }
}

TEST_CASE("truncated files in every format throw InputError", "[unit][image]") {
    TemporaryFolder folder;
    for (const std::string name : {"cut.exr", "cut.pfm", "cut.hdr", "cut.png"}) {
        INFO(name);
        write_image(folder.file(name), varied_image());
        const std::vector<unsigned char> whole = read_bytes(folder.file(name));
        for (const std::size_t kept : {whole.size() - 1, whole.size() / 2, std::size_t(20), std::size_t(3)}) {
            INFO("kept " << kept << " of " << whole.size() << " bytes");
            write_bytes(folder.file(name), std::vector<unsigned char>(whole.begin(), whole.begin() + long(kept)));
            CHECK_THAT(input_error_message([&] { read_image(folder.file(name)); }), Contains(folder.file(name)));
        }
    }
}

TEST_CASE("malformed PFM headers throw InputError with the reason", "[unit][image]") {
    TemporaryFolder folder;
    const std::string path = folder.file("bad.pfm");
    const std::vector<float> one_pixel = {1.0f, 2.0f, 3.0f};
    struct Case {
        std::string header;
        std::vector<float> values;
        std::string reason;
    };
    const std::vector<Case> cases = {
        {"P6\n1 1\n255\n", one_pixel, "PF"},                       // a PPM, not a PFM
        {"PFM\n1 1\n-1\n", one_pixel, "white space"},
        {"PF", {}, "width"},                                       // header ends at once
        {"PF\n1", {}, "height"},
        {"PF\n1 1\n-1", {}, "no pixel data"},
        {"PF\n1 x\n-1\n", one_pixel, "height 'x'"},
        {"PF\n1.5 1\n-1\n", one_pixel, "width '1.5'"},
        {"PF\n0 5\n-1\n", one_pixel, "invalid image size 0x5"},
        {"PF\n-3 5\n-1\n", one_pixel, "invalid image size -3x5"},
        {"PF\n100000 100000\n-1\n", one_pixel, "too large"},       // 10^10 pixels: refused before allocating
        {"PF\n4294967297 1\n-1\n", one_pixel, "too large"},        // 2^32 + 1 would wrap a 32-bit int
        {"PF\n99999999999999999999999 1\n-1\n", one_pixel, "not a whole number"},
        {"PF\n1 1\nnan\n", one_pixel, "scale 'nan'"},
        {"PF\n1 1\ninf\n", one_pixel, "scale 'inf'"},
        {"PF\n1 1\n0\n", one_pixel, "scale '0'"},
        {"PF\n1 1\nabc\n", one_pixel, "scale 'abc'"},
        {"PF\n2 1\n-1\n", one_pixel, "truncated"},                 // 2 pixels announced, 1 present
        {"PF\n1 1\n-1\n", {1.0f, 2.0f, 3.0f, 4.0f}, "unexpected bytes"},
    };
    for (const Case& bad : cases) {
        INFO(bad.header);
        write_file(path, bad.header, bad.values);
        CHECK_THAT(input_error_message([&] { read_image(path); }), Contains(path) && Contains(bad.reason));
    }
}

TEST_CASE("malformed Radiance HDR files throw InputError with the reason", "[unit][image]") {
    TemporaryFolder folder;
    const std::string path = folder.file("bad.hdr");
    struct Case {
        std::string header;
        std::vector<unsigned char> pixels;
        std::string reason;
    };
    const std::vector<Case> cases = {
        {"#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n", {1, 1, 1, 128}, "xyze"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", {}, "header ends"},
        {"#?RADIANCE\n\n+Y 1 +X 1\n", {1, 1, 1, 128}, "resolution line"},
        {"#?RADIANCE\n\n-Y 0 +X 1\n", {1, 1, 1, 128}, "invalid image size"},
        {"#?RADIANCE\n\n-Y -4 +X 1\n", {1, 1, 1, 128}, "invalid image size"},
        {"#?RADIANCE\n\n-Y 20000 +X 20000\n", {1, 1, 1, 128}, "too large"},
        {"#?RADIANCE\n\n-Y one +X 1\n", {1, 1, 1, 128}, "'one'"},
        {"#?RADIANCE\n\n-Y 1 +X 2\n", {1, 1, 1, 128}, "truncated"},                   // 2 pixels, 1 present
        // (The zeros after a broken count make the file long enough for an 8-pixel scanline, which
        // is checked before anything is decoded.)
        {"#?RADIANCE\n\n-Y 1 +X 8\n", {2, 2, 0, 8, 0, 0, 0, 0, 0, 0, 0, 0}, "run-length count"},     // a count of zero
        {"#?RADIANCE\n\n-Y 1 +X 8\n", {2, 2, 0, 8, 128 + 9, 1, 0, 0, 0, 0, 0, 0}, "run-length count"},  // 9 > 8 pixels
        {"#?RADIANCE\n\n-Y 1 +X 8\n", {2, 2, 0, 8, 128 + 8}, "truncated"},            // no run value
    };
    for (const Case& bad : cases) {
        INFO(bad.header);
        std::vector<unsigned char> bytes(bad.header.begin(), bad.header.end());
        bytes.insert(bytes.end(), bad.pixels.begin(), bad.pixels.end());
        write_bytes(path, bytes);
        CHECK_THAT(input_error_message([&] { read_image(path); }), Contains(path) && Contains(bad.reason));
    }
}

TEST_CASE("a PNG header announcing more than 2^28 pixels is refused before decoding", "[unit][image]") {
    TemporaryFolder folder;
    write_image(folder.file("huge.png"), Image(2, 2, Spectrum(0.5f)));
    std::vector<unsigned char> bytes = read_bytes(folder.file("huge.png"));
    // The IHDR chunk follows the 8-byte signature: length (4), "IHDR" (4), width (4), height (4).
    REQUIRE(std::string(bytes.begin() + 12, bytes.begin() + 16) == "IHDR");
    put_big_endian(bytes, 16, 16384);
    put_big_endian(bytes, 20, 17000);  // 278 million pixels: stb would try, we refuse
    write_bytes(folder.file("huge.png"), bytes);
    CHECK_THAT(input_error_message([&] { read_image(folder.file("huge.png")); }),
               Contains(folder.file("huge.png")) && Contains("too large"));
}

TEST_CASE("a JPEG far too short for the size its header claims is refused before decoding", "[unit][image]") {
    // Found by fuzz_image: 662 bytes claiming 65531 x 2300 pixels (at least 1 bit per 8x8 block:
    // 294 kB). The file without the fuzz target's first byte, which chose the extension.
    std::vector<unsigned char> bytes =
        read_bytes(std::string(FREEZERAY_SOURCE_DIR) + "/tests/fuzz/regressions/image/jpeg-huge-size-in-tiny-file.bin");
    REQUIRE(bytes.size() == 663);
    bytes.erase(bytes.begin());
    TemporaryFolder folder;
    write_bytes(folder.file("tiny.jpg"), bytes);
    CHECK_THAT(input_error_message([&] { read_image(folder.file("tiny.jpg")); }),
               Contains(folder.file("tiny.jpg")) && Contains("65531x2300") && Contains("truncated or corrupt"));

    // The fuzzer's valid JPEG seed (4 x 4, 662 bytes) is still read.
    bytes = read_bytes(std::string(FREEZERAY_SOURCE_DIR) + "/tests/fuzz/corpus/image/jpeg.bin");
    bytes.erase(bytes.begin());
    write_bytes(folder.file("seed.jpg"), bytes);
    const Image seed = read_image(folder.file("seed.jpg"));
    CHECK(seed.width() > 0);
}

TEST_CASE("a PIZ chunk whose bitmap runs past its end is refused", "[unit][image]") {
    // Found by fuzz_image when EXR went through tinyexr: a 192-byte PIZ chunk whose bitmap spans
    // bytes 0 to 227, which tinyexr copied from beyond the end of the file. OpenEXR's PIZ decoder
    // compares the bitmap with the chunk's size itself. The files without the fuzz target's first byte.
    const std::string folder_path = std::string(FREEZERAY_SOURCE_DIR) + "/tests/fuzz/";
    TemporaryFolder folder;
    std::vector<unsigned char> bytes = read_bytes(folder_path + "regressions/image/exr-piz-bitmap-past-end.bin");
    bytes.erase(bytes.begin());
    write_bytes(folder.file("piz.exr"), bytes);
    CHECK_THAT(input_error_message([&] { read_image(folder.file("piz.exr")); }),
               Contains(folder.file("piz.exr")) && Contains("cannot decode the OpenEXR pixels"));
    // A valid PIZ-compressed file (the fuzzer's seed) is still read.
    bytes = read_bytes(folder_path + "corpus/image/exr-piz-half.bin");
    bytes.erase(bytes.begin());
    write_bytes(folder.file("seed.exr"), bytes);
    CHECK(read_image(folder.file("seed.exr")).pixel_count() > 0);
}

TEST_CASE("an EXR data window of more than 2^28 pixels is refused before decoding", "[unit][image]") {
    TemporaryFolder folder;
    write_image(folder.file("huge.exr"), Image(2, 2, Spectrum(0.5f)));
    std::vector<unsigned char> bytes = read_bytes(folder.file("huge.exr"));
    // The attribute is: "dataWindow\0box2i\0", size (4 bytes), then min x, min y, max x, max y.
    const std::string name("dataWindow\0box2i\0", 17);
    const auto found = std::search(bytes.begin(), bytes.end(), name.begin(), name.end());
    REQUIRE(found != bytes.end());
    const std::size_t max_x = static_cast<std::size_t>(found - bytes.begin()) + name.size() + 4 + 8;
    // Max x and max y (little endian) set to 19999: a 20000 x 20000 window, 4 * 10^8 pixels.
    for (std::size_t at : {max_x, max_x + 4}) {
        const std::vector<unsigned char> value = {0x1f, 0x4e, 0, 0};  // 19999 = 0x4e1f
        std::copy(value.begin(), value.end(), bytes.begin() + long(at));
    }
    write_bytes(folder.file("huge.exr"), bytes);
    CHECK_THAT(input_error_message([&] { read_image(folder.file("huge.exr")); }), Contains(folder.file("huge.exr")));
}

namespace {

// The most memory this process has held at once so far, in kilobytes (getrusage, POSIX).
long peak_memory_kilobytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

}  // namespace

TEST_CASE("an EXR file claiming 16384 x 16384 pixels that holds 16 rows is refused without allocating the image",
          "[unit][image]") {
    // 2^28 pixels is the most we accept, 3 GB of our pixels: memory must follow what the file
    // really decodes, not what its header claims. The file: one valid ZIP block of 16 rows of
    // 16384 pixels, a header claiming 16384 rows, and all 1024 entries of the offset table
    // pointing at that block, so OpenEXR takes the file as complete and decodes the first block.
    TemporaryFolder folder;
    write_image(folder.file("claims.exr"), Image(16384, 16, Spectrum(0.5f)));
    const std::vector<unsigned char> written = read_bytes(folder.file("claims.exr"));
    const std::size_t header_end = exr_header_end(written);
    std::vector<unsigned char> bytes(written.begin(), written.begin() + long(header_end));
    put_little_endian(bytes, exr_attribute_value(bytes, "dataWindow", "box2i") + 12, 16383);  // max y
    const std::uint64_t block = header_end + 8 * 1024;
    for (int entry = 0; entry < 1024; ++entry) {
        for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<unsigned char>(block >> (8 * i)));
    }
    bytes.insert(bytes.end(), written.begin() + long(header_end + 8), written.end());
    write_bytes(folder.file("claims.exr"), bytes);

    const long before = peak_memory_kilobytes();
    CHECK_THAT(input_error_message([&] { read_image(folder.file("claims.exr")); }),
               Contains(folder.file("claims.exr")) && Contains("cannot decode the OpenEXR pixels"));
    CHECK(peak_memory_kilobytes() - before < 256 * 1024);
}

TEST_CASE("EXR header attributes are checked against the file before OpenEXR reads them", "[unit][image]") {
    TemporaryFolder folder;
    Image image(2, 2, Spectrum(0.5f));
    image.metadata = {{"freezeray:scene", "scene.json"}};
    write_image(folder.file("whole.exr"), image);
    const std::vector<unsigned char> whole = read_bytes(folder.file("whole.exr"));
    const auto refused_with = [&](const std::string& name, const std::vector<unsigned char>& bytes,
                                  const std::string& reason) {
        INFO(name);
        write_bytes(folder.file(name), bytes);
        CHECK_THAT(input_error_message([&] { read_image(folder.file(name)); }),
                   Contains(folder.file(name)) && Contains(reason));
    };

    // A string claiming 2^31 - 1 bytes: OpenEXR would allocate them before finding the file short.
    std::vector<unsigned char> bytes = whole;
    put_little_endian(bytes, exr_attribute_value(bytes, "freezeray:scene", "string") - 4, 0x7fffffff);
    refused_with("long-string.exr", bytes, "attribute 'freezeray:scene' runs past the end of the file");

    // A box2i declared 12 bytes long: OpenEXR reads 16 whatever the size says.
    bytes = whole;
    put_little_endian(bytes, exr_attribute_value(bytes, "dataWindow", "box2i") - 4, 12);
    refused_with("short-box.exr", bytes, "attribute 'dataWindow' of type box2i has 12 bytes, not 16");

    // A channel list whose end is cut off by its declared size.
    bytes = whole;
    const std::size_t channels = exr_attribute_value(bytes, "channels", "chlist");
    put_little_endian(bytes, channels - 4, 18 * 3);  // three channels of 18 bytes, no terminator
    refused_with("open-channel-list.exr", bytes, "the channel list ends inside a channel name");

    // A header cut inside the type name of its first attribute ("channels\0chlist\0", size, value).
    refused_with("no-end.exr", std::vector<unsigned char>(whole.begin(), whole.begin() + long(channels - 7)),
                 "the header ends inside an attribute type");
}

TEST_CASE("a file whose content does not match its extension throws InputError", "[unit][image]") {
    TemporaryFolder folder;
    write_image(folder.file("radiance.hdr"), varied_image());
    std::filesystem::copy_file(folder.file("radiance.hdr"), folder.file("radiance.png"));
    CHECK_THAT(input_error_message([&] { read_image(folder.file("radiance.png")); }),
               Contains(folder.file("radiance.png")) && Contains(".hdr"));

    write_image(folder.file("picture.png"), varied_image());
    std::filesystem::copy_file(folder.file("picture.png"), folder.file("picture.hdr"));
    std::filesystem::copy_file(folder.file("picture.png"), folder.file("picture.exr"));
    std::filesystem::copy_file(folder.file("picture.png"), folder.file("picture.pfm"));
    for (const std::string name : {"picture.hdr", "picture.exr", "picture.pfm"}) {
        CHECK_THAT(input_error_message([&] { read_image(folder.file(name)); }), Contains(folder.file(name)));
    }
}

TEST_CASE("corrupted bytes never crash a reader: it decodes or throws InputError", "[unit][image]") {
    TemporaryFolder folder;
    std::mt19937 random(20240613);  // fixed seed: the same corruptions on every run
    for (const std::string name : {"noisy.exr", "noisy.pfm", "noisy.hdr", "noisy.png"}) {
        INFO(name);
        write_image(folder.file(name), varied_image());
        const std::vector<unsigned char> whole = read_bytes(folder.file(name));
        std::uniform_int_distribution<std::size_t> position(0, whole.size() - 1);
        for (int trial = 0; trial < 150; ++trial) {
            std::vector<unsigned char> bytes = whole;
            const int changes = 1 + trial % 4;
            for (int i = 0; i < changes; ++i) bytes[position(random)] = static_cast<unsigned char>(random());
            write_bytes(folder.file(name), bytes);
            read_or_input_error(folder.file(name));
        }
        for (std::size_t kept = 1; kept < whole.size(); kept += 1 + whole.size() / 97) {
            write_bytes(folder.file(name), std::vector<unsigned char>(whole.begin(), whole.begin() + long(kept)));
            read_or_input_error(folder.file(name));
        }
    }
}

// stb_image reads past the end of its buffer as zeros, so without our checks a truncated JPEG,
// BMP or TGA would decode as an image with a black end (found by the fuzz_image target).
TEST_CASE("truncated JPEG, BMP and TGA files and unsupported stb formats throw InputError", "[unit][image]") {
    TemporaryFolder folder;
    const auto refused_with = [&](const std::string& name, const std::vector<unsigned char>& bytes,
                                  const std::string& reason) {
        INFO(name);
        write_bytes(folder.file(name), bytes);
        CHECK_THAT(input_error_message([&] { read_image(folder.file(name)); }),
                   Contains(folder.file(name)) && Contains(reason));
    };
    const auto little_endian = [](std::vector<unsigned char>& bytes, std::uint32_t value, int size) {
        for (int i = 0; i < size; ++i) bytes.push_back(static_cast<unsigned char>(value >> (8 * i)));
    };

    // A 4x4 JPEG written by stb_image_write (a seed of the fuzz_image corpus, after its selector byte).
    std::vector<unsigned char> jpeg = read_bytes(std::string(FREEZERAY_SOURCE_DIR) + "/tests/fuzz/corpus/image/jpeg.bin");
    REQUIRE(jpeg.size() > 100);
    jpeg.erase(jpeg.begin());
    write_bytes(folder.file("whole.jpg"), jpeg);
    CHECK(read_image(folder.file("whole.jpg")).width() == 4);
    refused_with("cut.jpg", std::vector<unsigned char>(jpeg.begin(), jpeg.end() - 40), "truncated");

    // A 64x64 24-bit BMP: 54 header bytes, then 64 rows of 192 bytes.
    std::vector<unsigned char> bmp = {'B', 'M'};
    little_endian(bmp, 54 + 64 * 192, 4);
    little_endian(bmp, 0, 4);
    little_endian(bmp, 54, 4);
    for (const std::uint32_t field : {40u, 64u, 64u}) little_endian(bmp, field, 4);
    little_endian(bmp, 1, 2);
    little_endian(bmp, 24, 2);
    for (int i = 0; i < 6; ++i) little_endian(bmp, 0, 4);
    bmp.resize(54 + 64 * 192, 128);
    write_bytes(folder.file("whole.bmp"), bmp);
    CHECK(read_image(folder.file("whole.bmp")).width() == 64);
    refused_with("cut.bmp", std::vector<unsigned char>(bmp.begin(), bmp.begin() + 54 + 10), "truncated");

    // A 16x16 uncompressed TGA, and a run-length one whose last packet is missing.
    std::vector<unsigned char> tga = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 16, 0, 16, 0, 24, 0};
    tga.resize(18 + 16 * 16 * 3, 200);
    write_bytes(folder.file("whole.tga"), tga);
    CHECK(read_image(folder.file("whole.tga")).width() == 16);
    refused_with("cut.tga", std::vector<unsigned char>(tga.begin(), tga.end() - 3), "truncated");
    std::vector<unsigned char> rle = {0, 0, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 16, 0, 16, 0, 24, 0};
    rle.insert(rle.end(), {0xff, 1, 2, 3});  // one run of 128 pixels: the other 128 are missing
    refused_with("cut-rle.tga", rle, "truncated");
    // Under another extension, bytes without a signature are not tried as TGA.
    refused_with("tga-named.png", tga, "not a valid PNG, JPEG or BMP file");

    refused_with("animation.png", {'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0, 0, 0}, "only PNG, JPEG, BMP and TGA");
    refused_with("portable.png", {'P', '6', '\n', '1', ' ', '1', '\n', '2', '5', '5', '\n', 1, 2, 3},
                 "only PNG, JPEG, BMP and TGA");
}
