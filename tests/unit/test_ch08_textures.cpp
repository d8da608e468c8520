// Chapter 08: tiled storage returns exactly the texels of row-major storage at every MIP level and
// in every format; 8-bit texels hold the decoded image exactly; the box filter keeps the mean;
// level selection and trilinear blending against exact answers; the pixel footprint against a
// plane seen head on; images bit-identical across layouts; concurrent lookups.
// Deterministic: no statistical test in this file.
#include "determinism.hpp"
#include "test_scenes.hpp"

#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/ch02/linear_layout.hpp"
#include "freezeray/ch03/register_chapter03.hpp"
#include "freezeray/ch04/register_chapter04.hpp"
#include "freezeray/ch05/register_chapter05.hpp"
#include "freezeray/ch06/register_chapter06.hpp"
#include "freezeray/ch07/register_chapter07.hpp"
#include "freezeray/ch08/mip_map.hpp"
#include "freezeray/ch08/mip_mapped_storage.hpp"
#include "freezeray/ch08/texel_addressing.hpp"
#include "freezeray/ch08/texel_format.hpp"
#include "freezeray/ch08/texture_layout_settings.hpp"
#include "freezeray/error.hpp"
#include "freezeray/random.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/ch08/texture_footprint.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <limits>
#include <set>
#include <thread>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch08;
using namespace freezeray::testing;

namespace {

bool same_bits(const Spectrum& a, const Spectrum& b) {
    for (int c = 0; c < 3; ++c)
        if (std::bit_cast<std::uint32_t>(a[c]) != std::bit_cast<std::uint32_t>(b[c])) return false;
    return true;
}

// An image whose texels are decodings of random bytes (as an 8-bit file gives), or random floats.
Image random_image(int width, int height, bool from_bytes, std::uint64_t seed) {
    PCG32 rng(seed, 1);
    Image image(width, height);
    for (Spectrum& texel : image.pixels())
        for (int c = 0; c < 3; ++c)
            texel[c] = from_bytes ? srgb_byte_decoding().value[static_cast<std::size_t>(rng.next_float() * 255.999f)]
                                  : 4.0f * rng.next_float();
    return image;
}

const MipMappedTexture& as_mip_mapped(const std::shared_ptr<const TextureStorage>& storage) {
    const auto* texture = dynamic_cast<const MipMappedTexture*>(storage.get());
    REQUIRE(texture != nullptr);
    return *texture;
}

}  // namespace

TEST_CASE("ch08: tiled_index gives every texel its own place inside the padded tiles", "[unit][ch08]") {
    for (const int tile_log2 : {1, 2, 3, 5}) {
        const int tile = 1 << tile_log2;
        const int width = 3 * tile + 1, height = 2 * tile - 1;  // partial tiles on both edges
        const std::size_t tiles_per_row = 4;                    // ceil(width / tile)
        const std::size_t capacity = tiles_per_row * 2 * static_cast<std::size_t>(tile * tile);
        std::set<std::size_t> seen;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t index = tiled_index(x, y, tile_log2, tiles_per_row);
                CHECK(index < capacity);
                seen.insert(index);
            }
        CHECK(seen.size() == static_cast<std::size_t>(width * height));
        // A tile's texels are consecutive: texel (tile - 1, tile - 1) ends the first tile, and
        // (tile, 0) starts the second.
        CHECK(tiled_index(tile - 1, tile - 1, tile_log2, tiles_per_row) == static_cast<std::size_t>(tile * tile - 1));
        CHECK(tiled_index(tile, 0, tile_log2, tiles_per_row) == static_cast<std::size_t>(tile * tile));
        CHECK(tiled_index(0, tile, tile_log2, tiles_per_row) == tiles_per_row * static_cast<std::size_t>(tile * tile));
    }
}

TEST_CASE("ch08: 8-bit texels hold an image from an 8-bit file exactly; others are kept in floats", "[unit][ch08]") {
    TextureLayoutSettings settings;
    settings.filter = TextureFilter::Bilinear;
    auto description = [&](const Image& image) { return as_mip_mapped(make_tiled_storage(image, settings)).description(); };
    const Image bytes = random_image(9, 5, true, 3);
    CHECK(description(bytes) == "tiled (4 x 4), 8-bit sRGB, 1 level");
    Image data(2, 1);
    data.at(0, 0) = Spectrum(data_byte_decoding().value[17]);
    data.at(1, 0) = Spectrum(data_byte_decoding().value[200]);
    CHECK(description(data) == "tiled (4 x 4), 8-bit data, 1 level");
    Image floats = bytes;
    floats.at(4, 2).g = std::nextafter(floats.at(4, 2).g, 2.0f);  // one value no byte decodes to (the last texel but four)
    CHECK(description(floats) == "tiled (4 x 4), float, 1 level");

    const auto stored = make_row_major_storage(bytes, settings);
    const MipMappedTexture& texture = as_mip_mapped(stored);
    CHECK(texture.memory_bytes() == 4u * 9u * 5u);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 9; ++x) CHECK(same_bits(texture.texel(x, y), bytes.at(x, y)));
    const auto stored_floats = make_row_major_storage(floats, settings);
    const MipMappedTexture& in_floats = as_mip_mapped(stored_floats);
    CHECK(in_floats.memory_bytes() == 12u * 9u * 5u);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 9; ++x) CHECK(same_bits(in_floats.texel(x, y), floats.at(x, y)));
}

TEST_CASE("ch08: a byte texel's code is the one whose value is nearest, the lower of two equally near", "[unit][ch08]") {
    // Against a search of all 256 codes, for both decodings: every code's own value, the values
    // a float step either side of it, midpoints between neighbours (ties), random values in and
    // out of [0, 1]; then infinities and NaN, which go to the ends of the table.
    for (const ByteDecoding* decoding : byte_decodings()) {
        const ByteTexels texels{decoding};
        auto nearest = [&](float x) {
            int best = 0;
            for (int c = 1; c < 256; ++c)
                if (std::abs(x - decoding->value[static_cast<std::size_t>(c)]) <
                    std::abs(x - decoding->value[static_cast<std::size_t>(best)]))
                    best = c;
            return best;
        };
        std::vector<float> values{0.0f, -0.0f, -1.0f, 1.0f, 2.0f, 1e-30f};
        for (int c = 0; c < 256; ++c) {
            const float v = decoding->value[static_cast<std::size_t>(c)];
            values.insert(values.end(), {v, std::nextafter(v, -1.0f), std::nextafter(v, 2.0f)});
            if (c < 255) values.push_back(0.5f * (v + decoding->value[static_cast<std::size_t>(c + 1)]));
        }
        PCG32 random(808, 8);
        for (int i = 0; i < 20000; ++i) values.push_back(1.2f * random.next_float() - 0.1f);
        for (const float x : values) {
            INFO(decoding->name << " decoding, x = " << x);
            const Spectrum value(x, x, x);
            REQUIRE(static_cast<int>(texels.encode(value).code[0]) == nearest(x));
            const std::optional<ByteTexels::Stored> exact = texels.encode_exactly(value);
            const bool held = std::bit_cast<std::uint32_t>(decoding->value[static_cast<std::size_t>(nearest(x))]) ==
                              std::bit_cast<std::uint32_t>(x);
            REQUIRE(exact.has_value() == held);
        }
        const float nan = std::numeric_limits<float>::quiet_NaN(), infinity = std::numeric_limits<float>::infinity();
        CHECK(texels.encode(Spectrum(infinity)).code[0] == 255);
        CHECK(texels.encode(Spectrum(-infinity)).code[0] == 0);
        CHECK(texels.encode(Spectrum(nan, nan, nan)).code[0] == 0);
        CHECK_FALSE(texels.encode_exactly(Spectrum(nan, nan, nan)).has_value());
    }
}

TEST_CASE("ch08: a MIP level is the exact box average of the level below, for any size", "[unit][ch08]") {
    SECTION("2 x 2 texels average to one; 3 texels in a row to one third each") {
        Image square(2, 2);
        square.at(0, 0) = Spectrum(1.0f);
        square.at(1, 0) = Spectrum(2.0f);
        square.at(0, 1) = Spectrum(3.0f);
        square.at(1, 1) = Spectrum(6.0f);
        const Image one = next_mip_level(square);
        REQUIRE(one.width() == 1);
        CHECK(one.at(0, 0).r == 3.0f);
        Image row(3, 1);
        row.at(0, 0) = Spectrum(3.0f);
        row.at(1, 0) = Spectrum(6.0f);
        row.at(2, 0) = Spectrum(9.0f);
        CHECK(next_mip_level(row).at(0, 0).r == Approx(6.0f).epsilon(1e-7));
    }
    SECTION("5 x 3 -> 2 x 1 keeps the mean; the pyramid ends at 1 x 1") {
        const Image image = random_image(5, 3, false, 7);
        const std::vector<Image> pyramid = build_mip_pyramid(image);
        REQUIRE(pyramid.size() == 3);  // 1 + floor(log2 5)
        CHECK(pyramid[1].width() == 2);
        CHECK(pyramid[1].height() == 1);
        CHECK(pyramid[2].width() == 1);
        double mean = 0.0;
        for (const Spectrum& t : image.pixels()) mean += t.g;
        mean /= 15.0;
        // Each level's mean is the image's, up to float rounding of the stored averages.
        for (const Image& level : pyramid) {
            double level_mean = 0.0;
            for (const Spectrum& t : level.pixels()) level_mean += t.g;
            CHECK(level_mean / static_cast<double>(level.pixel_count()) == Approx(mean).epsilon(1e-6));
        }
    }
}

TEST_CASE("ch08: tiled storage returns the texels of linear storage at every level, in every format", "[unit][ch08]") {
    for (const bool from_bytes : {true, false})
        for (const auto& [width, height] : {std::pair{1, 1}, std::pair{5, 3}, std::pair{64, 64}, std::pair{37, 20}})
            for (const int tile_size : {2, 4, 8, 16, 32}) {
                INFO((from_bytes ? "bytes" : "floats") << ", " << width << " x " << height << ", tiles of " << tile_size);
                const Image image = random_image(width, height, from_bytes, static_cast<std::uint64_t>(width * 100 + height));
                TextureLayoutSettings settings;
                settings.tile_size = tile_size;
                const auto linear = make_row_major_storage(image, settings);
                const auto tiled = make_tiled_storage(image, settings);
                const MipMappedTexture& a = as_mip_mapped(linear);
                const MipMappedTexture& b = as_mip_mapped(tiled);
                REQUIRE(a.level_count() == b.level_count());
                CHECK(a.level_count() == 1 + static_cast<int>(std::floor(std::log2(std::max(width, height)))));
                // In floats, the levels are build_mip_pyramid's exactly.
                const std::vector<Image> pyramid = build_mip_pyramid(image);
                REQUIRE(static_cast<int>(pyramid.size()) == a.level_count());
                bool identical = true, as_pyramid = true;
                for (int level = 0; level < a.level_count(); ++level) {
                    REQUIRE(a.level_width(level) == b.level_width(level));
                    REQUIRE(a.level_height(level) == b.level_height(level));
                    REQUIRE(a.level_width(level) == pyramid[static_cast<std::size_t>(level)].width());
                    for (int y = 0; y < a.level_height(level); ++y)
                        for (int x = 0; x < a.level_width(level); ++x) {
                            identical = identical && same_bits(a.level_texel(level, x, y), b.level_texel(level, x, y));
                            as_pyramid = as_pyramid && (from_bytes || same_bits(a.level_texel(level, x, y),
                                                                                pyramid[static_cast<std::size_t>(level)].at(x, y)));
                        }
                }
                CHECK(identical);
                CHECK(as_pyramid);
                CHECK(b.memory_bytes() >= a.memory_bytes());  // tiles pad, rows do not
            }
}

TEST_CASE("ch08: with the bilinear filter, lookups are chapter 02's, bit for bit", "[unit][ch08]") {
    const Image image = random_image(23, 17, true, 11);
    const ch02::LinearTextureStorage chapter02(image);
    TextureLayoutSettings settings;
    settings.filter = TextureFilter::Bilinear;
    for (const TexelFormatChoice format : {TexelFormatChoice::Auto, TexelFormatChoice::Float}) {
        settings.format = format;
        const auto linear = make_row_major_storage(image, settings);
        const auto tiled = make_tiled_storage(image, settings);
        PCG32 rng(5, 1);
        bool identical = true;
        for (int i = 0; i < 2000; ++i) {
            const TextureLookup lookup{Vec2(3.0f * rng.next_float() - 1.0f, 3.0f * rng.next_float() - 1.0f),
                                       Vec2(0.1f * rng.next_float()), Vec2(0.0f)};
            for (const WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp, WrapMode::Mirror}) {
                const Spectrum expected = chapter02.lookup(lookup, wrap);
                identical = identical && same_bits(linear->lookup(lookup, wrap), expected) &&
                            same_bits(tiled->lookup(lookup, wrap), expected);
            }
        }
        CHECK(identical);
    }
}

TEST_CASE("ch08: the MIP level is log2 of the longer step in texels", "[unit][ch08]") {
    CHECK(mip_level(Vec2(1.0f / 256.0f, 0.0f), Vec2(0.0f, 1.0f / 256.0f), 256, 256) == 0.0f);
    CHECK(mip_level(Vec2(4.0f / 256.0f, 0.0f), Vec2(0.0f, 1.0f / 256.0f), 256, 128) == 2.0f);
    CHECK(mip_level(Vec2(0.0f, 1.0f / 256.0f), Vec2(0.0f, 8.0f / 512.0f), 64, 512) == 3.0f);  // v in texels of 512
    CHECK(mip_level(Vec2(3.0f / 64.0f, 4.0f / 64.0f), Vec2(0.0f), 64, 64) == Approx(std::log2(5.0f)));
    CHECK(mip_level(Vec2(0.0f), Vec2(0.0f), 64, 64) == 0.0f);                     // nothing known
    CHECK(mip_level(Vec2(1.0f / 1024.0f, 0.0f), Vec2(0.0f), 256, 256) == -2.0f);  // magnified
}

TEST_CASE("ch08: a trilinear lookup reads the level of its footprint, and blends between two", "[unit][ch08]") {
    const Image image = random_image(64, 64, false, 13);
    const auto storage = make_tiled_storage(image, TextureLayoutSettings{});
    const MipMappedTexture& texture = as_mip_mapped(storage);
    REQUIRE(texture.level_count() == 7);
    const Vec2 uv(0.3f, 0.6f);
    auto footprint = [&](float level) { return TextureLookup{uv, Vec2(std::exp2(level) / 64.0f, 0.0f), Vec2(0.0f)}; };
    for (int level = 0; level < 7; ++level)
        CHECK(same_bits(storage->lookup(footprint(static_cast<float>(level)), WrapMode::Repeat),
                        texture.level_lookup(level, uv, WrapMode::Repeat)));
    const Spectrum halfway = storage->lookup(footprint(2.5f), WrapMode::Repeat);
    const Spectrum expected = 0.5f * texture.level_lookup(2, uv, WrapMode::Repeat) + 0.5f * texture.level_lookup(3, uv, WrapMode::Repeat);
    for (int c = 0; c < 3; ++c) CHECK(halfway[c] == Approx(expected[c]).epsilon(1e-6));
    // Beyond the last level: the last; a point: level 0.
    CHECK(same_bits(storage->lookup(footprint(20.0f), WrapMode::Repeat), texture.level_lookup(6, uv, WrapMode::Repeat)));
    CHECK(same_bits(storage->lookup(TextureLookup{uv}, WrapMode::Repeat), texture.level_lookup(0, uv, WrapMode::Repeat)));
}

TEST_CASE("ch08: concurrent lookups on one texture return what one thread gets", "[unit][ch08]") {
    const Image image = random_image(512, 256, true, 17);
    const auto storage = make_tiled_storage(image, TextureLayoutSettings{});
    std::vector<TextureLookup> lookups;
    PCG32 rng(19, 1);
    for (int i = 0; i < 20000; ++i)
        lookups.push_back({Vec2(rng.next_float(), rng.next_float()), Vec2(0.02f * rng.next_float(), 0.0f),
                           Vec2(0.0f, 0.02f * rng.next_float())});
    std::vector<Spectrum> expected;
    for (const TextureLookup& l : lookups) expected.push_back(storage->lookup(l, WrapMode::Repeat));
    constexpr int Threads = 4;
    std::vector<int> mismatches(Threads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < Threads; ++t)
        threads.emplace_back([&, t] {
            for (int pass = 0; pass < 5; ++pass)
                for (std::size_t i = 0; i < lookups.size(); ++i) {
                    const std::size_t j = (i * 7919 + static_cast<std::size_t>(t) * 104729) % lookups.size();
                    if (!same_bits(storage->lookup(lookups[j], WrapMode::Repeat), expected[j])) ++mismatches[t];
                }
        });
    for (std::thread& thread : threads) thread.join();
    for (int t = 0; t < Threads; ++t) CHECK(mismatches[t] == 0);
}

TEST_CASE("ch08: the footprint of a pixel on a square seen head on is the pixel's size over the square's", "[unit][ch08]") {
    // A square of side 2 at distance 4, uv from 0 to 1 across it, seen from the origin with a
    // 256-pixel-high image: one pixel spans spread = 2 tan(fov / 2) / 256 at distance 1, so
    // 4 spread in the plane and 4 spread / 2 in u and in v.
    TriangleMesh mesh;
    mesh.positions = {Vec3(-1.0f, -1.0f, 4.0f), Vec3(1.0f, -1.0f, 4.0f), Vec3(1.0f, 1.0f, 4.0f)};
    mesh.uvs = {Vec2(0.0f, 0.0f), Vec2(1.0f, 0.0f), Vec2(1.0f, 1.0f)};
    mesh.triangles = {{0u, 1u, 2u}};
    CameraDescription description;
    description.position = Vec3(0.0f);
    description.look_at = Vec3(0.0f, 0.0f, 1.0f);
    description.fov_vertical_degrees = 30.0f;
    description.width = description.height = 256;
    const PinholeCamera camera(description);
    Hit hit;
    hit.position = Vec3(0.5f, -0.5f, 4.0f);
    hit.geometric_normal = Vec3(0.0f, 0.0f, -1.0f);
    hit.triangle = 0;
    add_texture_footprint(hit, mesh, camera);
    // The hit is off the axis: the neighbouring rays meet the plane a little further out, by
    // 1 / cos^2 of the angle to the normal at most (here cos^2 = 16 / 16.5).
    const float expected = 4.0f * camera.pixel_spread() / 2.0f;
    CHECK(glm::length(hit.duv_dx) == Approx(expected).epsilon(0.04));
    CHECK(glm::length(hit.duv_dy) == Approx(expected).epsilon(0.04));
    CHECK(std::abs(glm::dot(hit.duv_dx, hit.duv_dy)) < 0.04f * expected * expected);  // nearly at right angles
    // Head on at the axis's point, the footprint is exact.
    hit.position = Vec3(0.0f, 0.0f, 4.0f);
    add_texture_footprint(hit, mesh, camera);
    CHECK(glm::length(hit.duv_dx) == Approx(expected).epsilon(1e-5));
    // Seen edge on (the normal across the ray), no footprint can be found: the whole texture.
    hit.geometric_normal = Vec3(1.0f, 0.0f, 0.0f);
    add_texture_footprint(hit, mesh, camera);
    CHECK(hit.duv_dx == Vec2(1.0f));
}

TEST_CASE("ch08: hits carry the footprint only when a texture layout filters by it", "[unit][ch08]") {
    // material-spheres' floor is textured; its camera's central ray meets a sphere or the floor,
    // so look down a column of the image for the first textured hit.
    auto first_textured_hit = [](const Scene& scene) -> std::optional<Hit> {
        const Camera& camera = *scene.camera;
        for (int y = camera.height() - 1; y >= 0; --y) {
            const std::optional<Hit> hit = scene.intersect(camera.generate_ray(Vec2(camera.width() / 2 + 0.5f, y + 0.5f)));
            if (hit && scene.material(*hit).is_textured()) return hit;
        }
        return std::nullopt;
    };
    const std::string path = scene_path("material-spheres/scene.json");
    // The complete renderer's default: trilinear, which reads the footprint.
    const Scene trilinear = load_scene(path, full_registry());
    REQUIRE(trilinear.texture_footprint != nullptr);
    const std::optional<Hit> with = first_textured_hit(trilinear);
    REQUIRE(with);
    CHECK(glm::length(with->duv_dx) > 0.0f);
    // The bilinear filter, and chapter 07's renderer (chapter 02's layout): no footprint, and
    // the same hit otherwise.
    SceneLoadOptions bilinear_options;
    bilinear_options.options.values["filter"] = "bilinear";
    Registry chapter07("ch07", 7);
    register_chapter07(chapter07);
    for (const Scene& scene : {load_scene(path, full_registry(), bilinear_options), load_scene(path, chapter07)}) {
        CHECK(scene.texture_footprint == nullptr);
        const std::optional<Hit> without = first_textured_hit(scene);
        REQUIRE(without);
        CHECK(without->duv_dx == Vec2(0.0f));
        CHECK(without->duv_dy == Vec2(0.0f));
        CHECK(without->position == with->position);
    }
}

TEST_CASE("ch08: images are the same, bit for bit, in the linear and the tiled layout", "[unit][ch08]") {
    TestRender request;
    request.scene = scene_path("material-spheres/scene.json");
    request.integrator = "pt-mis";
    request.samples_per_pixel = 2;
    request.width = 64;
    request.height = 48;
    for (const char* format : {"auto", "float"}) {
        INFO("texel format " << format);
        request.texture_settings = {{"layout", "linear"}, {"texel_format", format}};
        const RenderResult linear = render(request);
        request.texture_settings = {{"layout", "tiled"}, {"texel_format", format}};
        const RenderResult tiled = render(request);
        CHECK(bit_identical(linear.image, tiled.image));
    }
    // Without MIP levels, chapter 08 renders chapter 02's image: the footprint changes nothing else.
    request.texture_settings = {{"layout", "tiled"}, {"filter", "bilinear"}};
    const RenderResult bilinear = render(request);
    request.texture_settings = {{"layout", "tiled"}, {"filter", "trilinear"}};
    const RenderResult trilinear = render(request);
    CHECK(!bit_identical(bilinear.image, trilinear.image));  // the floor's checker is seen minified
}

TEST_CASE("ch08: texture settings outside their choices are refused at their key", "[unit][ch08]") {
    auto error_of = [](const nlohmann::json& block) {
        const Parameters parameters(block, "scene.json", "/textures", ".");
        try {
            read_texture_layout_settings(parameters);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    CHECK_THAT(error_of({{"filter", "nearest"}}), Catch::Contains("/textures/filter") && Catch::Contains("bilinear, trilinear"));
    CHECK_THAT(error_of({{"texel_format", "half"}}), Catch::Contains("/textures/texel_format"));
    CHECK_THAT(error_of({{"tile_size", 3}}), Catch::Contains("/textures/tile_size") && Catch::Contains("not 3"));
    CHECK(error_of({{"filter", "bilinear"}, {"texel_format", "float"}, {"tile_size", 32}}).empty());
}
