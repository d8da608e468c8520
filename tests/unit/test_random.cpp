// PCG32 against the reference implementation's published output, and stream independence.
#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <set>

using namespace freezeray;

TEST_CASE("PCG32 reproduces the reference sequence of pcg32-demo (seed 42, stream 54)", "[unit][random]") {
    // First outputs of O'Neill's pcg32-global-demo with pcg32_srandom_r(&rng, 42u, 54u).
    PCG32 random(42u, 54u);
    const std::uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e};
    for (std::uint32_t e : expected) CHECK(random.next_uint() == e);
}

TEST_CASE("next_float stays below 1 and next_below stays below its bound", "[unit][random]") {
    PCG32 random(7, 3);
    for (int i = 0; i < 100000; ++i) {
        const float f = random.next_float();
        REQUIRE(f >= 0.0f);
        REQUIRE(f < 1.0f);
        REQUIRE(random.next_below(7) < 7u);
    }
}

TEST_CASE("pixel streams differ across pixels, samples and seeds, and repeat for the same key", "[unit][random]") {
    std::set<std::uint32_t> first_values;
    for (std::uint32_t pixel = 0; pixel < 64; ++pixel)
        for (std::uint64_t sample = 0; sample < 64; ++sample) first_values.insert(make_pixel_stream(3, pixel, sample).next_uint());
    // 4096 keys into 2^32 values: a collision has probability about 4096^2 / 2^33 = 0.002.
    CHECK(first_values.size() >= 4095u);
    CHECK(make_pixel_stream(3, 10, 20).next_uint() == make_pixel_stream(3, 10, 20).next_uint());
    CHECK(make_pixel_stream(3, 10, 20).next_uint() != make_pixel_stream(4, 10, 20).next_uint());
}
