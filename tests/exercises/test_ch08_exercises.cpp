// Grading tests of chapter 08's exercises. Each calls its exercise's own code first (so that in a
// student copy it fails through its own stub) and checks it against exact answers: the index of
// every texel of a tiled image, and MIP levels of footprints whose lengths are powers of two.
// Deterministic: no statistical test in this file.
#include "freezeray/ch08/mip_map.hpp"
#include "freezeray/ch08/texel_addressing.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>

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
