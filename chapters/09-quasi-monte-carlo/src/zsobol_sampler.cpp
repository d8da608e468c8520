// The Morton-ordered Sobol sampler (book chapter 09; Ahmed and Wonka 2020; pbrt-v4's
// ZSobolSampler, Pharr, Jakob and Humphreys 2023, section 8.7.7).
#include "freezeray/ch09/zsobol_sampler.hpp"

#include "freezeray/ch09/fixed_point.hpp"
#include "freezeray/ch09/owen_scrambling.hpp"
#include "freezeray/ch09/radical_inverse.hpp"
#include "freezeray/ch09/scrambled_sobol.hpp"
#include "freezeray/random.hpp"

#include <algorithm>
#include <bit>

namespace freezeray::ch09 {

namespace {

// The 24 permutations of {0, 1, 2, 3}, in lexicographic order.
constexpr std::uint8_t DigitPermutations[24][4] = {
    {0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 3, 2, 1},
    {1, 0, 2, 3}, {1, 0, 3, 2}, {1, 2, 0, 3}, {1, 2, 3, 0}, {1, 3, 0, 2}, {1, 3, 2, 0},
    {2, 0, 1, 3}, {2, 0, 3, 1}, {2, 1, 0, 3}, {2, 1, 3, 0}, {2, 3, 0, 1}, {2, 3, 1, 0},
    {3, 0, 1, 2}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 1, 2, 0}, {3, 2, 0, 1}, {3, 2, 1, 0}};

// x's bits in the even places and y's in the odd ones: the Morton (Z-order) code of (x, y).
std::uint32_t morton_code(std::uint32_t x, std::uint32_t y) {
    std::uint32_t code = 0;
    for (int bit = 0; bit < 16; ++bit)
        code |= ((x >> bit) & 1u) << (2 * bit) | ((y >> bit) & 1u) << (2 * bit + 1);
    return code;
}

int ceil_log2(std::uint64_t n) { return n <= 1 ? 0 : static_cast<int>(std::bit_width(n - 1)); }

}  // namespace

void ZSobolSampler::plan_render(int width, int height, std::uint64_t samples_per_pixel) {
    epoch_log2_ = samples_per_pixel == 0 ? DefaultEpochLog2 : std::min(ceil_log2(samples_per_pixel), MaximumEpochLog2);
    // The Morton code and the sample's number share one 32-bit index.
    const int image_log2 = ceil_log2(static_cast<std::uint64_t>(std::max({width, height, 1})));
    tile_log2_ = std::min({image_log2, (32 - epoch_log2_) / 2, 10});
    last_x_ = -1;  // every cached block is stale
}

void ZSobolSampler::begin(int x, int y, std::uint32_t pixel_index, std::uint64_t sample_index) {
    const std::uint64_t epoch = sample_index >> epoch_log2_;
    index_in_epoch_ = static_cast<std::uint32_t>(sample_index & ((std::uint64_t{1} << epoch_log2_) - 1));
    sample_index_ = sample_index;
    pixel_key_ = pixel_key(seed(), pixel_index, 0x3c6ef372fe94f82bULL);
    if (x != last_x_ || y != last_y_ || epoch != last_epoch_ || seed() != last_seed_) {
        const auto ux = static_cast<std::uint32_t>(x), uy = static_cast<std::uint32_t>(y);
        const std::uint32_t mask = (1u << tile_log2_) - 1;
        morton_ = morton_code(ux & mask, uy & mask);
        const std::uint64_t tile = static_cast<std::uint64_t>(uy >> tile_log2_) << 32 | (ux >> tile_log2_);
        tile_key_ = mix_bits(mix_bits(seed() ^ 0xa54ff53a5f1d36f1ULL) + mix_bits(tile ^ mix_bits(epoch + 0x510e527fULL)));
        last_x_ = x;
        last_y_ = y;
        last_epoch_ = epoch;
        last_seed_ = seed();
        ++stamp_;
    }
}

// BOOK(zsobol-index)
std::uint32_t ZSobolSampler::sequence_index(std::uint32_t set) {
    Block& block = blocks_[set];
    if (block.stamp != stamp_) {
        // The Morton code's base-4 digits from the top (one digit: which quarter of its parent
        // square the pixel is in), each permuted by a permutation chosen by the digits above it:
        // Owen scrambling in base 4. Pixels under one parent keep their parent's block.
        const std::uint64_t key = dimension_key(set);
        std::uint32_t permuted = 0;
        for (int level = tile_log2_ - 1; level >= 0; --level) {
            const std::uint32_t digit = (morton_ >> (2 * level)) & 3u;
            const std::uint32_t above = morton_ >> (2 * level + 2);
            const std::uint64_t hash = mix_bits(key ^ (static_cast<std::uint64_t>(above) << 5 | static_cast<std::uint64_t>(level)));
            const auto choice = static_cast<std::uint32_t>(((hash >> 32) * 24) >> 32);  // uniform in 0 .. 23
            permuted |= static_cast<std::uint32_t>(DigitPermutations[choice][digit]) << (2 * level);
        }
        block.start = permuted << epoch_log2_;
        block.shuffle_seed = static_cast<std::uint32_t>(mix_bits(key + morton_));
        block.stamp = stamp_;
    }
    // The sample's number in the pixel, shuffled by a nested scramble of its L bits: bit i of the
    // result depends on bits i and above, so samples 0 .. 2^m - 1 still fill one aligned block
    // of 2^m (a net), while neighbouring pixels take their points in different orders.
    const std::uint32_t within = epoch_log2_ == 0 ? 0u
        : nested_uniform_scramble(index_in_epoch_, block.shuffle_seed) & ((1u << epoch_log2_) - 1);
    return block.start | within;
}

float ZSobolSampler::sample_1d(const Draw& draw) {
    const DrawPlace place = draw_place(draw);
    if (place.dimension >= QuasiRandomDimensions) return hashed_random(place.dimension);
    const std::uint32_t index = reverse_bits(sequence_index(place.set));
    // One Owen scramble per dimension for the whole tile: a scramble per pixel would undo the
    // quads' complementary blocks.
    const auto scramble_seed = static_cast<std::uint32_t>(dimension_key(place.dimension) >> 32);
    return fraction_to_float(scrambled_sobol_coordinate(tables_, index, place.coordinate, scramble_seed));
}

Vec2 ZSobolSampler::sample_2d(const Draw& draw) {
    const DrawPlace place = draw_place(draw);
    if (place.dimension + 1 >= QuasiRandomDimensions)
        return Vec2(hashed_random(place.dimension), hashed_random(place.dimension + 1));
    const std::uint32_t index = reverse_bits(sequence_index(place.set));
    const auto scramble_seed = static_cast<std::uint32_t>(dimension_key(place.dimension) >> 32);
    return scrambled_sobol_pair(tables_, index, place.coordinate, scramble_seed);
}
// END BOOK

float ZSobolSampler::hashed_random(std::uint32_t dimension) const {
    return hashed_uniform(mix_bits(mix_bits(pixel_key_ + dimension) ^ mix_bits(sample_index_)));
}

}  // namespace freezeray::ch09
