// Grading tests of chapter 08's exercises. Each calls its exercise's own code first (so that in a
// student copy it fails through its own stub) and checks it against exact answers: the index of
// every texel of a tiled image, MIP levels of footprints whose lengths are powers of two, and
// the next MIP level against the box average computed directly from its definition.
// Deterministic: fixed seeds, no statistical test in this file.
#include "freezeray/ch08/mip_map.hpp"
#include "freezeray/ch08/texel_addressing.hpp"
#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch08;

TEST_CASE("ch08/tile-offset", "[exercise]") {
    // Tiles of 4 x 4 texels, 3 tiles across: texel (5, 6) is in tile (1, 1), the fifth tile
    // (index 3 + 1 = 4, starting at texel 64), at row 2, column 1 of it: 64 + 2 * 4 + 1 = 73.
    CHECK(tiled_index(5, 6, 2, 3) == 73u);
    CHECK(tiled_index(0, 0, 2, 3) == 0u);
    CHECK(tiled_index(3, 3, 2, 3) == 15u);   // the last texel of the first tile
    CHECK(tiled_index(4, 0, 2, 3) == 16u);   // the first texel of the second
    CHECK(tiled_index(11, 3, 2, 3) == 47u);  // the last texel of the first row of tiles
    CHECK(tiled_index(0, 4, 2, 3) == 48u);
    // Every tile size, every texel of a 40 x 24 image, against the definition written out with
    // divisions and remainders.
    for (int log2 = 0; log2 <= 5; ++log2) {
        const int tile = 1 << log2;
        const std::size_t across = static_cast<std::size_t>((40 + tile - 1) / tile);
        for (int y = 0; y < 24; ++y)
            for (int x = 0; x < 40; ++x) {
                const std::size_t expected =
                    (static_cast<std::size_t>(y / tile) * across + static_cast<std::size_t>(x / tile)) * tile * tile +
                    static_cast<std::size_t>((y % tile) * tile + x % tile);
                INFO("tile " << tile << ", texel (" << x << ", " << y << ")");
                REQUIRE(tiled_index(x, y, log2, across) == expected);
            }
    }
}

TEST_CASE("ch08/mip-level", "[exercise]") {
    // One texel per pixel: level 0; 2^k texels per pixel: level k, whichever step is longer.
    CHECK(mip_level(Vec2(1.0f / 512.0f, 0.0f), Vec2(0.0f, 1.0f / 512.0f), 512, 512) == 0.0f);
    CHECK(mip_level(Vec2(8.0f / 512.0f, 0.0f), Vec2(0.0f, 1.0f / 512.0f), 512, 512) == 3.0f);
    CHECK(mip_level(Vec2(0.0f, 1.0f / 512.0f), Vec2(0.0f, 32.0f / 512.0f), 512, 512) == 5.0f);
    // u counts texels of the width, v of the height.
    CHECK(mip_level(Vec2(4.0f / 256.0f, 0.0f), Vec2(0.0f, 4.0f / 64.0f), 256, 64) == 2.0f);
    CHECK(mip_level(Vec2(0.0f, 16.0f / 64.0f), Vec2(0.0f), 256, 64) == 4.0f);
    // A diagonal step: its length, not its largest coordinate (3-4-5).
    CHECK(mip_level(Vec2(3.0f / 128.0f, 4.0f / 128.0f), Vec2(0.0f), 128, 128) == Approx(std::log2(5.0f)).epsilon(1e-6));
    // Magnification is negative; no footprint at all is level 0.
    CHECK(mip_level(Vec2(0.25f / 64.0f, 0.0f), Vec2(0.0f), 64, 64) == -2.0f);
    CHECK(mip_level(Vec2(0.0f), Vec2(0.0f), 64, 64) == 0.0f);
}

namespace {

// The next level's texel (x, y) computed directly from the definition: along each axis, texel i
// of n' = max(1, n / 2) covers [i n, (i + 1) n) in units of 1 / n' of the level below, texel k
// below covers [k n', (k + 1) n'), and the weight is their overlap divided by n (integers, so
// exact), the sum over every texel below (brute force, no taps).
glm::dvec3 box_average(const Image& level, int x, int y) {
    auto weight = [](int n, int i, int k) {
        const int next = std::max(1, n / 2);
        const int overlap = std::min((i + 1) * n, (k + 1) * next) - std::max(i * n, k * next);
        return overlap > 0 ? static_cast<double>(overlap) / n : 0.0;
    };
    glm::dvec3 sum(0.0);
    for (int j = 0; j < level.height(); ++j)
        for (int k = 0; k < level.width(); ++k)
            sum += weight(level.width(), x, k) * weight(level.height(), y, j) * glm::dvec3(level.at(k, j));
    return sum;
}

Image random_image(int width, int height, PCG32& random) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.at(x, y) = Spectrum(random.next_float(), 4.0f * random.next_float(), 0.01f * random.next_float());
    return image;
}

}  // namespace

TEST_CASE("ch08/mip-pyramid", "[exercise]") {
    // 5 x 3: 2 x 1 texels; texel 0 covers x in [0, 2.5) (weights 0.4, 0.4, 0.2) and all of y.
    Image small(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) small.at(x, y) = Spectrum(static_cast<float>(x), static_cast<float>(y), 1.0f);
    const Image first = next_mip_level(small);
    REQUIRE(first.width() == 2);
    REQUIRE(first.height() == 1);
    CHECK(first.at(0, 0).x == Approx(0.4 * 0 + 0.4 * 1 + 0.2 * 2).margin(1e-6));  // 0.8
    CHECK(first.at(1, 0).x == Approx(0.2 * 2 + 0.4 * 3 + 0.4 * 4).margin(1e-6));  // 3.2
    CHECK(first.at(0, 0).y == Approx(1.0).margin(1e-6));
    CHECK(first.at(1, 0).z == Approx(1.0).margin(1e-6));

    // Every size from 1 x 1 to 13 x 13 and a few long or large ones, random texels, against the
    // direct computation; sizes max(1, floor(n / 2)).
    PCG32 random(88, 8);
    std::vector<std::pair<int, int>> sizes;
    for (int w = 1; w <= 13; ++w)
        for (int h = 1; h <= 13; ++h) sizes.emplace_back(w, h);
    for (const auto& size : {std::pair{37, 1}, {1, 37}, {64, 48}, {33, 65}, {2, 31}, {127, 3}}) sizes.push_back(size);
    for (const auto& [w, h] : sizes) {
        if (w == 1 && h == 1) continue;
        const Image level = random_image(w, h, random);
        const Image next = next_mip_level(level);
        INFO("a level of " << w << " x " << h);
        REQUIRE(next.width() == std::max(1, w / 2));
        REQUIRE(next.height() == std::max(1, h / 2));
        for (int y = 0; y < next.height(); ++y)
            for (int x = 0; x < next.width(); ++x) {
                const glm::dvec3 expected = box_average(level, x, y);
                for (int c = 0; c < 3; ++c) {
                    INFO("texel (" << x << ", " << y << "), channel " << c << ": the exact average is " << expected[c]);
                    REQUIRE(next.at(x, y)[c] == Approx(expected[c]).epsilon(1e-6).margin(1e-9));
                }
            }
    }

    // A constant image stays exactly that constant at every size (the weights sum to 1, the sum
    // is rounded once), and the pyramid ends, after 1 + floor(log2(max(w, h))) levels, in one
    // texel that is the image's mean.
    for (const auto& [w, h] : {std::pair{7, 5}, {9, 1}, {1, 11}, {13, 13}, {6, 10}}) {
        const Image constant(w, h, Spectrum(0.3f, 0.7f, 1.1f));
        const Image next = next_mip_level(constant);
        for (int y = 0; y < next.height(); ++y)
            for (int x = 0; x < next.width(); ++x) {
                INFO("a constant level of " << w << " x " << h << ", texel (" << x << ", " << y << ")");
                REQUIRE(next.at(x, y).x == 0.3f);
                REQUIRE(next.at(x, y).y == 0.7f);
                REQUIRE(next.at(x, y).z == 1.1f);
            }
    }
    for (const auto& [w, h] : {std::pair{45, 27}, {64, 64}, {3, 100}}) {
        const Image image = random_image(w, h, random);
        const std::vector<Image> pyramid = build_mip_pyramid(image);
        glm::dvec3 mean(0.0);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) mean += glm::dvec3(image.at(x, y));
        mean /= static_cast<double>(w) * h;
        INFO("the pyramid of " << w << " x " << h);
        REQUIRE(pyramid.size() == static_cast<std::size_t>(1 + std::floor(std::log2(std::max(w, h)))));
        REQUIRE(pyramid.back().width() == 1);
        REQUIRE(pyramid.back().height() == 1);
        for (int c = 0; c < 3; ++c) CHECK(pyramid.back().at(0, 0)[c] == Approx(mean[c]).epsilon(1e-5));
    }
}
