// Chapter 09's sequences and samplers: the Sobol points and the scrambled sampler's points are
// nets (every elementary interval counted), the stratified sampler stratifies each block, the
// scramble keeps what it must and randomizes the rest, and every number depends only on (seed,
// pixel, sample index, dimension), the zsobol sampler's pixel quads are nets together, and the
// draws of a joint set are one Sobol point, as stratified as the sequence in every projection.
// Deterministic except the six chi-square tests of the scrambles' randomness (three for sobol,
// three for zsobol; label unit, unit_test_alpha each; tests/STATISTICS.md counts them).
#include "freezeray/ch09/owen_scrambling.hpp"
#include "freezeray/ch09/radical_inverse.hpp"
#include "freezeray/ch09/scrambled_sobol.hpp"
#include "freezeray/ch09/sobol_matrices.hpp"
#include "freezeray/ch09/sobol_sampler.hpp"
#include "freezeray/ch09/stratified_sampler.hpp"
#include "freezeray/ch09/zsobol_sampler.hpp"
#include "freezeray/random.hpp"

#include "statistics.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch09;

namespace {

// True when the 2^m points are a (0, m, 2)-net in base 2: for every a = 0 .. m, each of the 2^m
// boxes of 2^-a by 2^-(m-a) holds exactly one point. `what` names the first failing shape.
bool is_02_net(const std::vector<Vec2>& points, int m, std::string& what) {
    const std::size_t n = std::size_t{1} << m;
    if (points.size() != n) {
        what = "not 2^m points";
        return false;
    }
    for (int a = 0; a <= m; ++a) {
        std::vector<int> count(n, 0);
        for (const Vec2& p : points) {
            if (!(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f)) {
                what = "a point outside [0, 1)^2";
                return false;
            }
            const auto i = static_cast<std::size_t>(std::ldexp(p.x, a));
            const auto j = static_cast<std::size_t>(std::ldexp(p.y, m - a));
            ++count[(i << (m - a)) | j];
        }
        for (int c : count)
            if (c != 1) {
                what = "boxes of 2^-" + std::to_string(a) + " x 2^-" + std::to_string(m - a);
                return false;
            }
    }
    return true;
}

// True when the 2^m numbers fill the 2^m intervals [j 2^-m, (j + 1) 2^-m) once each.
bool is_01_net(const std::vector<float>& values, int m) {
    const std::size_t n = std::size_t{1} << m;
    if (values.size() != n) return false;
    std::vector<int> count(n, 0);
    for (float v : values) {
        if (!(v >= 0.0f && v < 1.0f)) return false;
        ++count[static_cast<std::size_t>(std::ldexp(v, m))];
    }
    for (int c : count)
        if (c != 1) return false;
    return true;
}

// The draws of one pixel's samples [first, first + count) at one place of the layout.
enum class Drawn { Pixel, LightPosition1, BsdfDirection1, BsdfDirection4, LightChoice1, Roulette3, BsdfLobe16 };

Vec2 draw_2d(Sampler& s, Drawn d) {
    switch (d) {
        case Drawn::Pixel: return s.pixel_2d();
        case Drawn::LightPosition1: s.start_vertex(1); return s.get_2d(VertexDimension::LightPosition);
        case Drawn::BsdfDirection1: s.start_vertex(1); return s.get_2d(VertexDimension::BsdfDirection);
        default: s.start_vertex(4); return s.get_2d(VertexDimension::BsdfDirection);
    }
}

float draw_1d(Sampler& s, Drawn d) {
    switch (d) {
        case Drawn::LightChoice1: s.start_vertex(1); return s.get_1d(VertexDimension::LightChoice);
        case Drawn::Roulette3: s.start_vertex(3); return s.get_1d(VertexDimension::Roulette);
        default: s.start_vertex(16); return s.get_1d(VertexDimension::BsdfLobe);
    }
}

// The draws of samples first .. first + count - 1 of one pixel: `draw(sampler, d)` after each
// sample is started (draw_2d for points, draw_1d for values).
template <typename Value>
std::vector<Value> pixel_draws(Sampler& s, std::uint32_t pixel, std::uint64_t first, std::uint64_t count, Drawn d,
                               Value (*draw)(Sampler&, Drawn)) {
    std::vector<Value> draws;
    for (std::uint64_t i = first; i < first + count; ++i) {
        s.start_pixel_sample(static_cast<int>(pixel % 64), static_cast<int>(pixel / 64), pixel, i);
        draws.push_back(draw(s, d));
    }
    return draws;
}

std::vector<Vec2> pixel_points(Sampler& s, std::uint32_t pixel, std::uint64_t first, std::uint64_t count, Drawn d) {
    return pixel_draws<Vec2>(s, pixel, first, count, d, draw_2d);
}

std::vector<float> pixel_values(Sampler& s, std::uint32_t pixel, std::uint64_t first, std::uint64_t count, Drawn d) {
    return pixel_draws<float>(s, pixel, first, count, d, draw_1d);
}

// Pearson's chi-square statistic of points in a cells x cells grid against uniform, its p-value.
double uniform_grid_p_value(const std::vector<Vec2>& points, int cells) {
    std::vector<double> count(static_cast<std::size_t>(cells * cells), 0.0);
    for (const Vec2& p : points)
        ++count[static_cast<std::size_t>(static_cast<int>(p.y * cells) * cells + static_cast<int>(p.x * cells))];
    const double expected = static_cast<double>(points.size()) / (cells * cells);
    double chi2 = 0.0;
    for (double c : count) chi2 += (c - expected) * (c - expected) / expected;
    return stats::chi_square_survival(chi2, cells * cells - 1.0);
}

}  // namespace

TEST_CASE("reverse_bits is the base-2 radical inverse in 0.32 fixed point", "[unit][ch09]") {
    CHECK(reverse_bits(1u) == 0x80000000u);
    CHECK(reverse_bits(6u) == 0x60000000u);  // 110b -> 0.011b
    PCG32 random(5, 9);
    for (int i = 0; i < 1000; ++i) {
        const std::uint32_t x = random.next_uint();
        REQUIRE(reverse_bits(reverse_bits(x)) == x);
        REQUIRE(reverse_bits(x) * 0x1p-32 == radical_inverse(2, x));
    }
}

TEST_CASE("each Sobol dimension is a (0,1)-sequence and dimensions 0 and 1 a (0,2)-sequence", "[unit][ch09]") {
    // A (0, s)-sequence: every block of 2^m points from a multiple of 2^m is a (0, m, s)-net.
    for (int m = 0; m <= 12; ++m)
        for (std::uint32_t block : {0u, 1u, 5u}) {
            const std::uint32_t first = block << m;
            for (int d = 0; d < SobolDimensions; ++d) {
                std::vector<float> values;
                for (std::uint32_t i = first; i < first + (1u << m); ++i) values.push_back(sobol_sample(i, d));
                INFO("dimension " << d << ", m = " << m << ", block " << block);
                REQUIRE(is_01_net(values, m));
            }
            std::vector<Vec2> points;
            for (std::uint32_t i = first; i < first + (1u << m); ++i) points.emplace_back(sobol_sample(i, 0), sobol_sample(i, 1));
            std::string what;
            INFO("m = " << m << ", block " << block << ": " << what);
            REQUIRE(is_02_net(points, m, what));
        }
    // Dimension 0 is the van der Corput sequence.
    for (std::uint32_t i = 0; i < 4096; ++i) REQUIRE(sobol_sample_bits(i, 0) == reverse_bits(i));
    CHECK_THROWS_AS(sobol_generator_matrix(SobolDimensions), std::out_of_range);
    CHECK_THROWS_AS(sobol_generator_matrix(-1), std::out_of_range);
}

TEST_CASE("a nested uniform scramble flips each bit by a function of the bits above it", "[unit][ch09]") {
    PCG32 random(11, 3);
    for (int trial = 0; trial < 2000; ++trial) {
        const std::uint32_t seed = random.next_uint();
        const std::uint32_t x = random.next_uint();
        const int j = static_cast<int>(random.next_below(32));  // x and y share their top j bits
        const std::uint32_t high = j == 0 ? 0u : ~0u << (32 - j);
        const std::uint32_t y = (x & high) | (random.next_uint() & ~high);
        REQUIRE((nested_uniform_scramble(x, seed) & high) == (nested_uniform_scramble(y, seed) & high));
    }
    // A bijection: all 2^16 top halves go to 2^16 different top halves.
    std::set<std::uint32_t> images;
    for (std::uint32_t i = 0; i < 65536; ++i) images.insert(nested_uniform_scramble(i << 16, 0x1234567u) >> 16);
    CHECK(images.size() == 65536u);
    // And different seeds give different permutations.
    CHECK(nested_uniform_scramble(0x40000000u, 1) != nested_uniform_scramble(0x40000000u, 2));
}

TEST_CASE("a scrambled Sobol coordinate from the reversed tables is the nested scramble of the point", "[unit][ch09]") {
    // The samplers stay in reversed bit order from the shuffled index to the scramble
    // (scrambled_sobol.hpp); the number must be the one the definitions give.
    const SobolNibbleTables* tables = reversed_sobol_tables();
    PCG32 random(12, 5);
    for (int trial = 0; trial < 100000; ++trial) {
        const std::uint32_t index = trial < 1024 ? static_cast<std::uint32_t>(trial) : random.next_uint();
        const std::uint32_t seed = random.next_uint();
        const auto c = static_cast<std::uint32_t>(trial % SobolDimensions);
        INFO("index " << index << ", coordinate " << c);
        REQUIRE(multiply_by_nibbles(tables[c], reverse_bits(index)) == reverse_bits(sobol_sample_bits(index, static_cast<int>(c))));
        REQUIRE(scrambled_sobol_coordinate(tables, reverse_bits(index), c, seed) ==
                nested_uniform_scramble(sobol_sample_bits(index, static_cast<int>(c)), seed));
        // The samplers' tables, in the order of a joint set's coordinates.
        const std::uint32_t coordinate = c % MaxJointCoordinates;
        REQUIRE(scrambled_sobol_coordinate(joint_coordinate_tables(), reverse_bits(index), coordinate, seed) ==
                nested_uniform_scramble(sobol_sample_bits(index, JointCoordinateDimension[coordinate]), seed));
    }
}

namespace {

// REQUIREs that for seeds 0 and 77 and three pixels, the sampler's draws over samples
// [a 2^m, (a + 1) 2^m) are (0, m, 2)-nets in four 2D draws and (0, m, 1)-nets in three 1D draws,
// for m <= 10 and blocks a = 0, 1 and 6. `what` names the sampler in a failure.
void require_pixel_draws_are_nets(Sampler& sampler, const std::string& what) {
    for (std::uint64_t seed : {0ull, 77ull}) {
        sampler.set_seed(seed);
        for (std::uint32_t pixel : {0u, 1u, 4097u})
            for (int m = 0; m <= 10; ++m)
                for (std::uint64_t block : {0ull, 1ull, 6ull}) {
                    const std::uint64_t first = block << m, count = std::uint64_t{1} << m;
                    for (Drawn d : {Drawn::Pixel, Drawn::LightPosition1, Drawn::BsdfDirection1, Drawn::BsdfDirection4}) {
                        std::string why;
                        const bool net = is_02_net(pixel_points(sampler, pixel, first, count, d), m, why);
                        INFO(what << ", seed " << seed << ", pixel " << pixel << ", m = " << m << ", block " << block
                                  << ", draw " << static_cast<int>(d) << ": " << why);
                        REQUIRE(net);
                    }
                    for (Drawn d : {Drawn::LightChoice1, Drawn::Roulette3, Drawn::BsdfLobe16}) {
                        INFO(what << ", seed " << seed << ", pixel " << pixel << ", m = " << m << ", block " << block
                                  << ", 1D draw " << static_cast<int>(d));
                        REQUIRE(is_01_net(pixel_values(sampler, pixel, first, count, d), m));
                    }
                }
    }
}

// Samples 0 .. 4095 of pixel (7, 3) (index 199): each one's pixel x against vertex 1's light
// choice. Different dimensions must take the pixel's points in different orders (one shuffle for
// both would put every pair on the diagonal).
std::vector<Vec2> within_pixel_pairs(Sampler& sampler) {
    std::vector<Vec2> pairs;
    for (std::uint64_t i = 0; i < 4096; ++i) {
        sampler.start_pixel_sample(7, 3, 199, i);
        const float x = sampler.pixel_2d().x;
        sampler.start_vertex(1);
        pairs.emplace_back(x, sampler.get_1d(VertexDimension::LightChoice));
    }
    return pairs;
}

}  // namespace

TEST_CASE("the sobol sampler's draws over any 2^m samples of a pixel from a multiple of 2^m are nets", "[unit][ch09]") {
    SobolSampler sampler;
    require_pixel_draws_are_nets(sampler, "sobol");
}

TEST_CASE("the sobol sampler's scrambles make each point uniform and the pairs independent", "[unit][ch09]") {
    // Three chi-square tests of 4096 points in a 16 x 16 grid (255 degrees of freedom), each at
    // unit_test_alpha: (1) sample 3 of 4096 pixels, pixel position: the per-pixel scrambles must
    // spread it uniformly; (2) the same for vertex 2's light choice against vertex 5's roulette
    // across pixels: two dimensions of a pixel must not be tied; (3) within one pixel, 4096
    // samples' pixel x against vertex 1's light choice: different dimensions are shuffled
    // independently (the same shuffle would put every point on the diagonal).
    SobolSampler sampler;
    sampler.set_seed(3);
    std::vector<Vec2> across_pixels, two_dimensions;
    for (std::uint32_t pixel = 0; pixel < 4096; ++pixel) {
        sampler.start_pixel_sample(static_cast<int>(pixel % 64), static_cast<int>(pixel / 64), pixel, 3);
        across_pixels.push_back(sampler.pixel_2d());
        sampler.start_vertex(2);
        const float choice = sampler.get_1d(VertexDimension::LightChoice);
        sampler.start_vertex(5);
        two_dimensions.emplace_back(choice, sampler.get_1d(VertexDimension::Roulette));
    }
    CHECK(uniform_grid_p_value(across_pixels, 16) > stats::unit_test_alpha);
    CHECK(uniform_grid_p_value(two_dimensions, 16) > stats::unit_test_alpha);
    CHECK(uniform_grid_p_value(within_pixel_pairs(sampler), 16) > stats::unit_test_alpha);
}

TEST_CASE("permutation_element is a permutation of 0 .. n - 1 for every n and seed", "[unit][ch09]") {
    for (std::uint32_t n : {1u, 2u, 3u, 7u, 64u, 100u, 1000u, 1024u, 4097u})
        for (std::uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
            std::vector<int> hit(n, 0);
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t p = permutation_element(i, n, seed);
                REQUIRE(p < n);
                ++hit[p];
            }
            for (int h : hit) REQUIRE(h == 1);
        }
    // Different seeds, different permutations.
    int same = 0;
    for (std::uint32_t i = 0; i < 64; ++i) same += permutation_element(i, 64, 1) == permutation_element(i, 64, 2);
    CHECK(same < 32);
}

TEST_CASE("the stratified sampler stratifies every block of 1, 1, 2, 4, ... samples", "[unit][ch09]") {
    StratifiedSampler sampler;
    sampler.set_seed(5);
    for (int k = 0; k <= 10; ++k) {
        const std::uint64_t first = k == 0 ? 1 : std::uint64_t{1} << k, count = std::uint64_t{1} << k;
        for (Drawn d : {Drawn::Pixel, Drawn::BsdfDirection1, Drawn::BsdfDirection4}) {
            const std::vector<Vec2> points = pixel_points(sampler, 12, first, count, d);
            // The cells of the 2^ceil(k/2) x 2^floor(k/2) grid: the (a = ceil(k/2)) boxes of a net.
            const int columns_log2 = (k + 1) / 2;
            std::vector<int> cells(count, 0);
            for (const Vec2& p : points) {
                REQUIRE(p.x >= 0.0f);
                REQUIRE(p.x < 1.0f);
                REQUIRE(p.y >= 0.0f);
                REQUIRE(p.y < 1.0f);
                const auto column = static_cast<std::size_t>(std::ldexp(p.x, columns_log2));
                const auto row = static_cast<std::size_t>(std::ldexp(p.y, k - columns_log2));
                ++cells[(row << columns_log2) | column];
            }
            INFO("block of 2^" << k << ", draw " << static_cast<int>(d));
            for (int c : cells) REQUIRE(c == 1);
        }
        for (Drawn d : {Drawn::LightChoice1, Drawn::Roulette3}) {
            INFO("block of 2^" << k << ", 1D draw " << static_cast<int>(d));
            REQUIRE(is_01_net(pixel_values(sampler, 12, first, count, d), k));
        }
    }
    // Sample 0 is a block of its own, and so is sample 1: the two are independent draws, not
    // stratified together. Were they one block of 2, they would never fall in the same half of
    // [0, 1). Over 4000 pixels the count of pixels where they do is Binomial(4000, 1/2): mean
    // 2000, standard deviation 31.6; the bound of 5 deviations fails falsely with probability
    // 6e-7 (fixed seed: the outcome is deterministic).
    int same_half = 0;
    constexpr int pixels = 4000;
    for (std::uint32_t pixel = 0; pixel < pixels; ++pixel) {
        const std::vector<float> first_two = pixel_values(sampler, pixel, 0, 2, Drawn::LightChoice1);
        same_half += (first_two[0] < 0.5f) == (first_two[1] < 0.5f) ? 1 : 0;
    }
    INFO(same_half << " of " << pixels << " pixels have samples 0 and 1 in the same half");
    CHECK(std::abs(same_half - pixels / 2) < 5 * 31.6);
}

TEST_CASE("a sampler's numbers depend on (seed, pixel, sample, dimension) only", "[unit][ch09]") {
    // Each dimension's number is the same whatever else was drawn before it, in whichever sampler
    // (a clone on another thread): the pixel loop's results cannot depend on the thread or order.
    SobolSampler sobol;
    StratifiedSampler stratified;
    ZSobolSampler zsobol;
    zsobol.plan_render(16, 16, 64);
    for (Sampler* s : {static_cast<Sampler*>(&sobol), static_cast<Sampler*>(&stratified), static_cast<Sampler*>(&zsobol)}) {
        s->set_seed(42);
        s->start_pixel_sample(3, 4, 259, 37);
        const Vec2 pixel = s->pixel_2d();
        s->start_vertex(2);
        const float roulette = s->get_1d(VertexDimension::Roulette);
        const Vec2 light = s->get_2d(VertexDimension::LightPosition);

        const auto other = s->clone();
        other->start_pixel_sample(9, 9, 9, 9);  // somewhere else first
        other->pixel_2d();
        other->start_pixel_sample(3, 4, 259, 37);
        other->start_vertex(2);
        CHECK(other->get_2d(VertexDimension::LightPosition) == light);  // in another order
        CHECK(other->get_1d(VertexDimension::Roulette) == roulette);
        CHECK(other->pixel_2d() == pixel);

        other->set_seed(43);  // another seed: other numbers
        other->start_pixel_sample(3, 4, 259, 37);
        CHECK(other->pixel_2d() != pixel);
    }
}

namespace {

// The draws of samples 0 .. count - 1 of every pixel of the square of side `side` whose corner
// is (x0, y0), pooled.
template <typename Value>
std::vector<Value> square_draws(Sampler& s, int x0, int y0, int side, std::uint64_t count, Drawn d,
                                Value (*draw)(Sampler&, Drawn)) {
    std::vector<Value> draws;
    for (int y = y0; y < y0 + side; ++y)
        for (int x = x0; x < x0 + side; ++x)
            for (std::uint64_t i = 0; i < count; ++i) {
                s.start_pixel_sample(x, y, static_cast<std::uint32_t>(y * 64 + x), i);
                draws.push_back(draw(s, d));
            }
    return draws;
}

}  // namespace

TEST_CASE("the zsobol sampler plans its epoch and tiles from the render's size", "[unit][ch09]") {
    ZSobolSampler sampler;
    CHECK(sampler.epoch_log2() == ZSobolSampler::DefaultEpochLog2);
    sampler.plan_render(64, 64, 100);  // 100 samples: blocks of 128
    CHECK(sampler.epoch_log2() == 7);
    CHECK(sampler.tile_log2() == 6);  // one 64 x 64 tile
    sampler.plan_render(64, 64, 128);
    CHECK(sampler.epoch_log2() == 7);
    sampler.plan_render(64, 64, 1);
    CHECK(sampler.epoch_log2() == 0);
    sampler.plan_render(1920, 1080, 128);  // 2048 wide: tiles of 1024, the most a 32-bit index allows
    CHECK(sampler.tile_log2() == 10);
    sampler.plan_render(1920, 1080, std::uint64_t{1} << 20);  // 20 bits of sample number leave 12 for the tile
    CHECK(sampler.epoch_log2() == 20);
    CHECK(sampler.tile_log2() == 6);
    sampler.plan_render(64, 64, std::uint64_t{1} << 30);  // epochs of at most 2^20
    CHECK(sampler.epoch_log2() == ZSobolSampler::MaximumEpochLog2);
    sampler.plan_render(64, 64, 0);  // a time budget: the count is unknown
    CHECK(sampler.epoch_log2() == ZSobolSampler::DefaultEpochLog2);
    CHECK(sampler.tile_log2() == 6);
}

TEST_CASE("the zsobol sampler's draws over any 2^m samples of a pixel from a multiple of 2^m are nets", "[unit][ch09]") {
    // Blocks inside the first epoch (block 0, and 1 while 2^(m+1) <= 2^L) and in later epochs
    // (block 6 at m = 10 is epoch 6), for the planned count and for a time budget (no plan).
    for (std::uint64_t planned : {std::uint64_t{1024}, std::uint64_t{0}}) {
        ZSobolSampler sampler;
        sampler.plan_render(64, 64, planned);
        require_pixel_draws_are_nets(sampler, "zsobol planned for " + std::to_string(planned) + " spp");
    }
}

TEST_CASE("the zsobol sampler's aligned squares of 2^k x 2^k pixels are nets together", "[unit][ch09]") {
    // With 2^L samples per pixel planned, the 4^k 2^L samples of an aligned square of 2^k x 2^k
    // pixels are one block of the sequence: a (0, L + 2k, 2)-net in every 2D draw and a
    // (0, L + 2k, 1)-net in every 1D one, and this is what makes the image's error blue noise.
    // Odd and even L, squares in several places of the tile.
    for (int L : {0, 3, 4}) {
        ZSobolSampler sampler;
        sampler.plan_render(64, 64, std::uint64_t{1} << L);
        sampler.set_seed(static_cast<std::uint64_t>(L) + 5);
        for (int k : {1, 2})
            for (auto [x0, y0] : {std::pair{0, 0}, std::pair{4, 8}, std::pair{60, 36}}) {
                const int side = 1 << k, m = L + 2 * k;
                for (Drawn d : {Drawn::Pixel, Drawn::BsdfDirection1, Drawn::BsdfDirection4}) {
                    std::string what;
                    const bool net = is_02_net(square_draws<Vec2>(sampler, x0, y0, side, std::uint64_t{1} << L, d, draw_2d), m, what);
                    INFO("L = " << L << ", square of " << side << " at (" << x0 << ", " << y0 << "), draw "
                                << static_cast<int>(d) << ": " << what);
                    REQUIRE(net);
                }
                for (Drawn d : {Drawn::LightChoice1, Drawn::Roulette3}) {
                    INFO("L = " << L << ", square of " << side << " at (" << x0 << ", " << y0 << "), 1D draw "
                                << static_cast<int>(d));
                    REQUIRE(is_01_net(square_draws<float>(sampler, x0, y0, side, std::uint64_t{1} << L, d, draw_1d), m));
                }
            }
    }
}

TEST_CASE("the zsobol sampler's scrambles make each point uniform and the dimensions independent", "[unit][ch09]") {
    // Three chi-square tests of 4096 points in a 16 x 16 grid (255 degrees of freedom), each at
    // unit_test_alpha: (1) one pixel's sample 3 over 4096 seeds: the randomization makes every
    // point uniform; (2) vertex 2's light choice against vertex 5's roulette over those seeds: two
    // dimensions are not tied; (3) within one pixel, 4096 samples' pixel x against vertex 1's
    // light choice: the dimensions take the pixel's points in different orders.
    ZSobolSampler sampler;
    sampler.plan_render(64, 64, 4096);
    std::vector<Vec2> over_seeds, two_dimensions;
    for (std::uint64_t seed = 0; seed < 4096; ++seed) {
        sampler.set_seed(seed);
        sampler.start_pixel_sample(21, 9, 9 * 64 + 21, 3);
        over_seeds.push_back(sampler.pixel_2d());
        sampler.start_vertex(2);
        const float choice = sampler.get_1d(VertexDimension::LightChoice);
        sampler.start_vertex(5);
        two_dimensions.emplace_back(choice, sampler.get_1d(VertexDimension::Roulette));
    }
    sampler.set_seed(3);
    CHECK(uniform_grid_p_value(over_seeds, 16) > stats::unit_test_alpha);
    CHECK(uniform_grid_p_value(two_dimensions, 16) > stats::unit_test_alpha);
    CHECK(uniform_grid_p_value(within_pixel_pairs(sampler), 16) > stats::unit_test_alpha);
}

namespace {

// The t of the smallest-t (t, m, s)-net the 2^m points' projection on `coordinates` is: for
// every split of m - t bits among the coordinates, each box of that shape holds 2^t points.
int net_t_value(const std::vector<std::vector<float>>& points, const std::vector<std::size_t>& coordinates, int m) {
    const std::size_t s = coordinates.size();
    for (int t = 0; t < m; ++t) {
        const int k = m - t;
        bool net = true;
        std::vector<int> bits(s, 0);  // a split of k bits: bits[0 .. s-2] chosen, the last gets the rest
        std::function<void(std::size_t, int)> split = [&](std::size_t c, int left) {
            if (!net) return;
            if (c + 1 == s) {
                bits[c] = left;
                std::vector<int> count(std::size_t{1} << k, 0);
                for (const std::vector<float>& p : points) {
                    std::size_t box = 0;
                    for (std::size_t i = 0; i < s; ++i)
                        box = (box << bits[i]) | static_cast<std::size_t>(std::ldexp(p[coordinates[i]], bits[i]));
                    ++count[box];
                }
                for (int n : count)
                    if (n != (1 << t)) net = false;
                return;
            }
            for (int b = 0; b <= left; ++b) {
                bits[c] = b;
                split(c + 1, left - b);
            }
        };
        split(0, k);
        if (net) return t;
    }
    return m;
}

// Every draw a vertex of the per-vertex layout makes, and which of them are pairs.
constexpr VertexDimension VertexDraws[] = {VertexDimension::LightChoice, VertexDimension::LightPosition,
                                           VertexDimension::BsdfDirection, VertexDimension::BsdfLobe,
                                           VertexDimension::Roulette};
bool is_pair(VertexDimension d) { return d == VertexDimension::LightPosition || d == VertexDimension::BsdfDirection; }

// Samples [first, first + count) of pixel 5: every draw of the per-vertex layout whose place is
// in joint set `set`, at its coordinates (a point per sample).
std::vector<std::vector<float>> joint_set_points(Sampler& s, std::uint32_t set, std::uint64_t first, std::uint64_t count) {
    std::vector<std::vector<float>> points;
    for (std::uint64_t i = first; i < first + count; ++i) {
        s.start_pixel_sample(5, 0, 5, i);
        std::vector<float> p(MaxJointCoordinates, -1.0f);
        for (int vertex = 1; vertex <= QuasiRandomVertices; ++vertex) {
            s.start_vertex(vertex);
            for (VertexDimension d : VertexDraws) {
                const DrawPlace place = vertex_draw_place(vertex, d);
                if (place.set != set) continue;
                if (is_pair(d)) {
                    const Vec2 u = s.get_2d(d);
                    p[place.coordinate] = u.x;
                    p[place.coordinate + 1] = u.y;
                } else {
                    p[place.coordinate] = s.get_1d(d);
                }
            }
        }
        points.push_back(p);
    }
    return points;
}

// REQUIREs that each tested joint set's draws over samples [a 2^m, (a + 1) 2^m) of a pixel are
// as well stratified as the Sobol sequence's first 2^m points in the same dimensions (those of
// the set's coordinates, JointCoordinateDimension): every pair and triple of coordinates, and the path set's first four
// (vertex 1's BSDF direction with vertex 2's light position), have the t of the sequence's
// projection. The shuffle and the scrambles move points between boxes of a shape, whole boxes
// to whole boxes, so the t is exactly the sequence's; sets drawn apart would not keep it.
void require_joint_sets_are_sobol_points(Sampler& sampler, const std::string& what) {
    const std::uint32_t vertex1_light = vertex_draw_place(1, VertexDimension::LightPosition).set;
    const std::uint32_t vertex4_bsdf = vertex_draw_place(4, VertexDimension::BsdfDirection).set;
    for (std::uint32_t set : {vertex1_light, PathSet, vertex4_bsdf}) {
        for (int m : {5, 8}) {
            // The sequence's own points and which coordinates the set uses.
            std::vector<std::vector<float>> sobol_points;
            for (std::uint32_t i = 0; i < (1u << m); ++i) {
                std::vector<float> p;
                for (int d : JointCoordinateDimension) p.push_back(sobol_sample(i, d));
                sobol_points.push_back(p);
            }
            for (std::uint64_t block : {0ull, 5ull}) {
                const auto points = joint_set_points(sampler, set, block << m, std::uint64_t{1} << m);
                std::vector<std::size_t> used;
                for (std::size_t c = 0; c < MaxJointCoordinates; ++c)
                    if (points[0][c] >= 0.0f) used.push_back(c);
                std::vector<std::vector<std::size_t>> projections;
                for (std::size_t a = 0; a < used.size(); ++a)
                    for (std::size_t b = a + 1; b < used.size(); ++b) {
                        projections.push_back({used[a], used[b]});
                        for (std::size_t c = b + 1; c < used.size(); ++c) projections.push_back({used[a], used[b], used[c]});
                    }
                if (set == PathSet) projections.push_back({0, 1, 2, 3});
                for (const auto& projection : projections) {
                    std::string coordinates;
                    for (std::size_t c : projection) coordinates += std::to_string(c) + " ";
                    INFO(what << ", set " << set << ", m = " << m << ", block " << block << ", coordinates " << coordinates);
                    REQUIRE(net_t_value(points, projection, m) == net_t_value(sobol_points, projection, m));
                }
            }
        }
    }
}

}  // namespace

TEST_CASE("the per-vertex layout gives every draw its own dimension and coordinates in its set", "[unit][ch09]") {
    // Over every vertex: dimensions never shared (a pair takes two), within a set no coordinate
    // taken twice, every coordinate below MaxJointCoordinates, and the documented sets.
    std::set<std::uint32_t> dimensions;
    std::set<std::pair<std::uint32_t, std::uint32_t>> coordinates;  // (set, coordinate)
    for (int vertex = 1; vertex <= QuasiRandomVertices + 2; ++vertex)
        for (VertexDimension d : VertexDraws) {
            const DrawPlace place = vertex_draw_place(vertex, d);
            const bool pair = is_pair(d);
            INFO("vertex " << vertex << ", draw " << static_cast<int>(d));
            CHECK(place.dimension == CameraDimensions + DimensionsPerVertex * (vertex - 1) + static_cast<std::uint32_t>(d));
            for (std::uint32_t k = 0; k < (pair ? 2u : 1u); ++k) {
                CHECK(dimensions.insert(place.dimension + k).second);
                CHECK(coordinates.insert({place.set, place.coordinate + k}).second);
                CHECK(place.coordinate + k < MaxJointCoordinates);
            }
            const bool in_path = vertex <= JointPathVertices && (vertex > 1 || d == VertexDimension::BsdfDirection ||
                                                                   d == VertexDimension::BsdfLobe);
            if (d == VertexDimension::Roulette) CHECK(place.set == place.dimension);
            else if (in_path) CHECK(place.set == PathSet);
            else if (d == VertexDimension::LightChoice) CHECK(place == DrawPlace{place.dimension, place.dimension + 1, 2});
            else if (d == VertexDimension::BsdfLobe) CHECK(place == DrawPlace{place.dimension, place.dimension - 2, 2});
            else CHECK(place == DrawPlace{place.dimension, place.dimension, 0});
        }
    CHECK(vertex_draw_place(1, VertexDimension::BsdfDirection) == DrawPlace{PathSet, PathSet, 0});
    CHECK(vertex_draw_place(2, VertexDimension::LightPosition).coordinate == 2);
}

TEST_CASE("the sobol sampler's joint sets are points of one Sobol sequence", "[unit][ch09]") {
    SobolSampler sampler;
    sampler.set_seed(21);
    require_joint_sets_are_sobol_points(sampler, "sobol");
}

TEST_CASE("the zsobol sampler's joint sets are points of one Sobol sequence", "[unit][ch09]") {
    for (std::uint64_t planned : {std::uint64_t{256}, std::uint64_t{0}}) {
        ZSobolSampler sampler;
        sampler.set_seed(21);
        sampler.plan_render(64, 64, planned);
        require_joint_sets_are_sobol_points(sampler, "zsobol planned for " + std::to_string(planned) + " spp");
    }
}
