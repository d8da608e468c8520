// Textures: constants, bilinear filtering, wrap modes, the orientation of v, sRGB decoding of
// colour maps and raw values of data maps, and reading each file once.
#include "freezeray/ch02/image_texture.hpp"
#include "freezeray/ch02/texture.hpp"
#include "freezeray/ch02/linear_layout.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/random.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

using namespace freezeray;
using namespace freezeray::ch02;
using freezeray::testing::TemporaryFolder;

namespace {

// A 2 x 2 image with four distinct colours: a b on the top row, c d on the bottom row.
const Spectrum a(0.0f, 0.25f, 1.0f), b(1.0f, 0.5f, 0.0f), c(0.5f, 0.0f, 0.25f), d(0.25f, 1.0f, 0.5f);

Image two_by_two() {
    Image image(2, 2);
    image.at(0, 0) = a;
    image.at(1, 0) = b;
    image.at(0, 1) = c;
    image.at(1, 1) = d;
    return image;
}

// The centre of texel (x, y) of a 2 x 2 image in texture coordinates (v counts up from the bottom).
Vec2 centre_of_texel(int x, int y) { return Vec2((x + 0.5f) / 2.0f, 1.0f - (y + 0.5f) / 2.0f); }

void check_equal(const Spectrum& actual, const Spectrum& expected) {
    INFO("actual (" << actual.r << ", " << actual.g << ", " << actual.b << "), expected (" << expected.r << ", "
                    << expected.g << ", " << expected.b << ")");
    CHECK(actual.r == Approx(expected.r).margin(1e-6));
    CHECK(actual.g == Approx(expected.g).margin(1e-6));
    CHECK(actual.b == Approx(expected.b).margin(1e-6));
}

}  // namespace

TEST_CASE("a constant texture returns its value everywhere", "[unit][texture]") {
    const ConstantTexture<Spectrum> colour(Spectrum(0.1f, 0.2f, 0.3f));
    const ConstantTexture<float> number(0.7f);
    for (const Vec2 uv : {Vec2(0.0f), Vec2(0.3f, 0.9f), Vec2(-5.0f, 12.0f)}) {
        CHECK(colour.eval({uv}) == Spectrum(0.1f, 0.2f, 0.3f));
        CHECK(number.eval({uv}) == 0.7f);
    }
    CHECK(colour.is_constant());
    CHECK(number.minimum() == 0.7f);
    CHECK(number.maximum() == 0.7f);
}

TEST_CASE("bilinear filtering is exact at texel centres and midpoints of a 2x2 image", "[unit][texture]") {
    const LinearTextureStorage storage(two_by_two());
    const ImageTexture<Spectrum> texture(std::make_shared<LinearTextureStorage>(two_by_two()), WrapMode::Clamp);
    SECTION("texel centres give the texels") {
        check_equal(texture.eval({centre_of_texel(0, 0)}), a);
        check_equal(texture.eval({centre_of_texel(1, 0)}), b);
        check_equal(texture.eval({centre_of_texel(0, 1)}), c);
        check_equal(texture.eval({centre_of_texel(1, 1)}), d);
    }
    SECTION("midpoints give the means of their neighbours") {
        check_equal(texture.eval({Vec2(0.5f, 0.75f)}), (a + b) / 2.0f);  // between the top two
        check_equal(texture.eval({Vec2(0.25f, 0.5f)}), (a + c) / 2.0f);  // between the left two
        check_equal(texture.eval({Vec2(0.5f, 0.5f)}), (a + b + c + d) / 4.0f);
        // A quarter of the way from a to b along the top row.
        check_equal(texture.eval({Vec2(0.375f, 0.75f)}), 0.75f * a + 0.25f * b);
    }
    SECTION("the storage's range bounds every lookup") {
        CHECK(storage.minimum() == Spectrum(0.0f));
        CHECK(storage.maximum() == Spectrum(1.0f));
        CHECK(texture.minimum() == Spectrum(0.0f));
    }
}

TEST_CASE("wrap modes outside [0, 1]: repeat, clamp and mirror at -0.25 and 1.25", "[unit][texture]") {
    const auto storage = std::make_shared<LinearTextureStorage>(two_by_two());
    const float top = 0.75f;  // v of the top row's centres
    SECTION("repeat: the image starts over") {
        const ImageTexture<Spectrum> texture(storage, WrapMode::Repeat);
        check_equal(texture.eval({Vec2(-0.25f, top)}), b);  // as at u = 0.75
        check_equal(texture.eval({Vec2(1.25f, top)}), a);   // as at u = 0.25
        check_equal(texture.eval({Vec2(0.25f, -0.25f)}), a);  // as at v = 0.75: the top row
        check_equal(texture.eval({Vec2(0.25f, 1.25f)}), c);   // as at v = 0.25: the bottom row
        // Across the seam at u = 0 the last column blends with the first.
        check_equal(texture.eval({Vec2(0.0f, top)}), (a + b) / 2.0f);
    }
    SECTION("clamp: the edge texels stretch out") {
        const ImageTexture<Spectrum> texture(storage, WrapMode::Clamp);
        check_equal(texture.eval({Vec2(-0.25f, top)}), a);
        check_equal(texture.eval({Vec2(1.25f, top)}), b);
        check_equal(texture.eval({Vec2(0.25f, -0.25f)}), c);
        check_equal(texture.eval({Vec2(0.25f, 1.25f)}), a);
        check_equal(texture.eval({Vec2(0.0f, top)}), a);
    }
    SECTION("mirror: neighbouring copies are reflections") {
        const ImageTexture<Spectrum> texture(storage, WrapMode::Mirror);
        check_equal(texture.eval({Vec2(-0.25f, top)}), a);  // as at u = 0.25
        check_equal(texture.eval({Vec2(1.25f, top)}), b);   // as at u = 0.75
        check_equal(texture.eval({Vec2(0.25f, -0.25f)}), c);  // as at v = 0.25
        check_equal(texture.eval({Vec2(0.25f, 1.25f)}), a);   // as at v = 0.75
        check_equal(texture.eval({Vec2(0.0f, top)}), a);  // no seam: the edge meets itself
    }
}

TEST_CASE("wrap_texel_index maps any index into the row", "[unit][texture]") {
    CHECK(wrap_texel_index(-1, 4, WrapMode::Repeat) == 3);
    CHECK(wrap_texel_index(9, 4, WrapMode::Repeat) == 1);
    CHECK(wrap_texel_index(-1, 4, WrapMode::Clamp) == 0);
    CHECK(wrap_texel_index(9, 4, WrapMode::Clamp) == 3);
    CHECK(wrap_texel_index(-1, 4, WrapMode::Mirror) == 0);
    CHECK(wrap_texel_index(4, 4, WrapMode::Mirror) == 3);
    CHECK(wrap_texel_index(8, 4, WrapMode::Mirror) == 0);
    CHECK(wrap_texel_index(-5, 4, WrapMode::Mirror) == 3);
}

TEST_CASE("huge and non-finite texture coordinates stay inside the image", "[unit][texture][stability]") {
    const auto storage = std::make_shared<LinearTextureStorage>(two_by_two());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp, WrapMode::Mirror}) {
        const ImageTexture<Spectrum> texture(storage, wrap);
        for (const Vec2 uv : {Vec2(1e9f, -3e9f), Vec2(nan, 0.5f), Vec2(0.5f, infinity), Vec2(-1e30f, 1e30f)}) {
            const Spectrum value = texture.eval({uv});
            CHECK(is_valid_radiance(value));
            CHECK(max_component(value) <= 1.0f);
        }
    }
}

TEST_CASE("v = 0 is the bottom row of the image file, as in OBJ", "[unit][texture]") {
    const TemporaryFolder folder;
    Image image(1, 2);
    image.at(0, 0) = Spectrum(1.0f, 0.0f, 0.0f);  // top row: red
    image.at(0, 1) = Spectrum(0.0f, 0.0f, 1.0f);  // bottom row: blue
    write_image(folder.file("rows.png"), image);
    const ImageTexture<Spectrum> texture(load_texture_storage(folder.file("rows.png"), TextureEncoding::SRGB, testing::full_registry(), "linear"),
                                         WrapMode::Clamp);
    check_equal(texture.eval({Vec2(0.5f, 0.1f)}), Spectrum(0.0f, 0.0f, 1.0f));
    check_equal(texture.eval({Vec2(0.5f, 0.9f)}), Spectrum(1.0f, 0.0f, 0.0f));
}

TEST_CASE("a colour map is decoded from sRGB, a data map keeps its stored values", "[unit][texture]") {
    const TemporaryFolder folder;
    // An 8-bit file cannot hold 0.5 exactly: code 128 (0.502 encoded) decodes to 0.2158.
    write_image(folder.file("grey.png"), Image(1, 1, Spectrum(srgb_to_linear(128.0f / 255.0f))));
    const auto colour = load_texture_storage(folder.file("grey.png"), TextureEncoding::SRGB, testing::full_registry(), "linear");
    const auto data = load_texture_storage(folder.file("grey.png"), TextureEncoding::Linear, testing::full_registry(), "linear");
    CHECK(colour->texel(0, 0).g == Approx(srgb_to_linear(128.0f / 255.0f)).margin(1e-6));
    CHECK(colour->texel(0, 0).g == Approx(0.214f).margin(0.002));  // 0.5 encoded is 0.214 linear
    CHECK(data->texel(0, 0).g == Approx(128.0f / 255.0f).margin(1e-5));

    SECTION("floating-point files hold linear values in both encodings") {
        write_image(folder.file("grey.pfm"), Image(1, 1, Spectrum(0.5f)));
        CHECK(load_texture_storage(folder.file("grey.pfm"), TextureEncoding::SRGB, testing::full_registry(), "linear")->texel(0, 0).r == 0.5f);
        CHECK(load_texture_storage(folder.file("grey.pfm"), TextureEncoding::Linear, testing::full_registry(), "linear")->texel(0, 0).r == 0.5f);
    }
}

TEST_CASE("a float texture reads the first channel", "[unit][texture]") {
    const auto storage = std::make_shared<LinearTextureStorage>(Image(1, 1, Spectrum(0.25f, 0.5f, 0.75f)));
    const ImageTexture<float> texture(storage, WrapMode::Repeat);
    CHECK(texture.eval({Vec2(0.5f)}) == 0.25f);
    CHECK(texture.minimum() == 0.25f);
    CHECK(texture.maximum() == 0.25f);
    CHECK_FALSE(texture.is_constant());
}

TEST_CASE("a file is read once while textures use it", "[unit][texture]") {
    const TemporaryFolder folder;
    write_image(folder.file("shared.png"), Image(2, 2, Spectrum(0.5f)));
    const auto first = load_texture_storage(folder.file("shared.png"), TextureEncoding::SRGB, testing::full_registry(), "linear");
    const auto again = load_texture_storage(folder.path() + "/./shared.png", TextureEncoding::SRGB, testing::full_registry(), "linear");
    const auto as_data = load_texture_storage(folder.file("shared.png"), TextureEncoding::Linear, testing::full_registry(), "linear");
    CHECK(first.get() == again.get());
    CHECK(first.get() != as_data.get());
}

TEST_CASE("unreadable texture files are InputErrors naming the file or the texel", "[unit][texture]") {
    const TemporaryFolder folder;
    CHECK_THROWS_AS(load_texture_storage(folder.file("missing.png"), TextureEncoding::SRGB, testing::full_registry(), "linear"), InputError);
    Image bad(2, 1, Spectrum(0.5f));
    bad.at(1, 0).g = std::numeric_limits<float>::infinity();
    write_image(folder.file("bad.pfm"), bad);
    try {
        load_texture_storage(folder.file("bad.pfm"), TextureEncoding::Linear, testing::full_registry(), "linear");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("bad.pfm") && Catch::Contains("texel (1, 0)"));
    }
}

TEST_CASE("a texture lookup (one virtual call, texels read inline) equals the filter reading every texel through the "
          "virtual interface, bit for bit",
          "[unit][texture]") {
    // A 7 x 5 image of distinct values, so that any texel read from the wrong place shows.
    Image image(7, 5);
    PCG32 random(12345, 1);
    for (Spectrum& texel : image.pixels()) texel = Spectrum(random.next_float(), random.next_float(), random.next_float());
    const LinearTextureStorage linear(image);
    const TextureStorage& through_interface = linear;
    std::size_t differing = 0;
    for (const WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp, WrapMode::Mirror})
        for (int i = 0; i < 20000; ++i) {
            const Vec2 uv(4.0f * random.next_float() - 1.5f, 4.0f * random.next_float() - 1.5f);
            // bilinear_lookup<TextureStorage> calls the virtual texel four times: the path every
            // lookup took before layouts had their own lookup.
            const Spectrum reference = bilinear_lookup(through_interface, uv, wrap);
            const Spectrum value = through_interface.lookup({uv}, wrap);
            for (int c = 0; c < 3; ++c) differing += std::memcmp(&reference[c], &value[c], sizeof(float)) != 0;
        }
    CHECK(differing == 0u);
}
