// Jittered sampling in blocks of doubling size (book chapter 09).
#include "freezeray/ch09/stratified_sampler.hpp"

#include "freezeray/random.hpp"

#include <algorithm>
#include <bit>

namespace freezeray::ch09 {

std::uint32_t permutation_element(std::uint32_t i, std::uint32_t length, std::uint32_t p) {
    // A hash that is a bijection on the bits below the mask w (xor-shifts to the right of masked
    // bits, multiplications by odd constants), repeated while it lands past the end: cycle-walking.
    std::uint32_t w = length - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    do {
        i ^= p;
        i *= 0xe170893du;
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i *= 0x0929eb3fu;
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i *= 1u | p >> 27;
        i *= 0x6935fa69u;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303u;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3u;
        i ^= (i & w) >> 2;
        i *= 0xc860a3dfu;
        i &= w;
        i ^= i >> 5;
    } while (i >= length);
    return (i + p) % length;
}

void StratifiedSampler::begin(int, int, std::uint32_t pixel_index, std::uint64_t sample_index) {
    pixel_key_ = pixel_key(seed(), pixel_index, 0x2545f4914f6cdd1dULL);
    sample_index_ = sample_index;
    // Blocks: {0}, {1}, {2, 3}, {4 .. 7}, ...: sample s > 0 is in the block of 2^k from 2^k, k = floor(log2 s).
    const std::uint64_t s = std::min<std::uint64_t>(sample_index, 0x80000000u);  // blocks stop doubling at 2^31
    block_log2_ = s == 0 ? 0 : static_cast<int>(std::bit_width(s)) - 1;
    index_in_block_ = s == 0 ? 0 : static_cast<std::uint32_t>(s - (std::uint64_t{1} << block_log2_));
}

// BOOK(stratified-sampler)
std::uint32_t StratifiedSampler::stratum(std::uint32_t dimension) const {
    // The same permutation for every sample of the block: the samples take different strata.
    const std::uint64_t key = mix_bits(pixel_key_ ^ mix_bits((static_cast<std::uint64_t>(dimension) << 8) | block_log2_));
    return permutation_element(index_in_block_, 1u << block_log2_, static_cast<std::uint32_t>(key));
}

float StratifiedSampler::jitter(std::uint32_t dimension) const {
    return hashed_uniform(mix_bits(mix_bits(pixel_key_ + sample_index_) ^ dimension));
}

float StratifiedSampler::sample_1d(const Draw& draw) {
    const std::uint32_t dimension = draw.dimension;
    const double n = static_cast<double>(1u << block_log2_);
    return static_cast<float>(std::min((stratum(dimension) + jitter(dimension)) / n, 0x1.fffffep-1));
}

Vec2 StratifiedSampler::sample_2d(const Draw& draw) {
    const std::uint32_t dimension = draw.dimension;
    // A 2^ceil(k/2) x 2^floor(k/2) grid of cells for a block of 2^k samples.
    const int columns_log2 = (block_log2_ + 1) / 2;
    const std::uint32_t cell = stratum(dimension);
    const std::uint32_t column = cell & ((1u << columns_log2) - 1);
    const std::uint32_t row = cell >> columns_log2;
    const double columns = static_cast<double>(1u << columns_log2);
    const double rows = static_cast<double>(1u << (block_log2_ - columns_log2));
    return Vec2(static_cast<float>(std::min((column + jitter(dimension)) / columns, 0x1.fffffep-1)),
                static_cast<float>(std::min((row + jitter(dimension + 1)) / rows, 0x1.fffffep-1)));
}
// END BOOK

}  // namespace freezeray::ch09
