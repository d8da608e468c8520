// The Owen-scrambled Sobol sampler (book chapter 09; Burley 2020, section 4).
#include "freezeray/ch09/sobol_sampler.hpp"

#include "freezeray/ch09/fixed_point.hpp"
#include "freezeray/ch09/owen_scrambling.hpp"
#include "freezeray/ch09/radical_inverse.hpp"
#include "freezeray/ch09/sobol_matrices.hpp"
#include "freezeray/random.hpp"

namespace freezeray::ch09 {

void SobolSampler::begin(int, int, std::uint32_t pixel_index, std::uint64_t sample_index) {
    pixel_key_ = pixel_key(seed(), pixel_index, 0x5851f42d4c957f2dULL);
    sample_index_ = sample_index;
    reversed_sample_index_ = reverse_bits(static_cast<std::uint32_t>(sample_index));
}

std::uint64_t SobolSampler::dimension_key(std::uint32_t dimension) const { return mix_bits(pixel_key_ + dimension); }

float SobolSampler::hashed_random(std::uint32_t dimension) const {
    return hashed_uniform(mix_bits(dimension_key(dimension) ^ mix_bits(sample_index_)));
}

// BOOK(sobol-sampler)
std::uint32_t SobolSampler::shuffled_index(std::uint64_t key) const {
    // The index shuffled by a nested scramble: the samples a 2^m to (a + 1) 2^m - 1 of a pixel
    // become, up to a digital shift, the sequence's first 2^m points in another order, a
    // (0, m, 2)-net. Indices past 2^32 wrap (4 billion samples of one pixel). This is
    // nested_uniform_scramble(index, seed), its first reversal done once per sample in begin().
    return reverse_bits(laine_karras_permutation(reversed_sample_index_, static_cast<std::uint32_t>(key)));
}

float SobolSampler::sample_1d(std::uint32_t dimension) {
    if (dimension >= QuasiRandomDimensions) return hashed_random(dimension);
    const std::uint64_t key = dimension_key(dimension);
    const std::uint32_t index = shuffled_index(key);
    // Sobol dimension 0 is the van der Corput sequence: the index's bits reversed.
    return fraction_to_float(scrambled_van_der_corput(index, static_cast<std::uint32_t>(key >> 32)));
}

Vec2 SobolSampler::sample_2d(std::uint32_t dimension) {
    if (dimension + 1 >= QuasiRandomDimensions) return Vec2(hashed_random(dimension), hashed_random(dimension + 1));
    const std::uint64_t key = dimension_key(dimension);
    const std::uint32_t index = shuffled_index(key);
    const std::uint32_t y = sobol_sample_bits(index, 1);
    const auto scramble_seed = static_cast<std::uint32_t>(key >> 32);
    return Vec2(fraction_to_float(scrambled_van_der_corput(index, hash_combine(scramble_seed, 0))),
                fraction_to_float(nested_uniform_scramble(y, hash_combine(scramble_seed, 1))));
}
// END BOOK

}  // namespace freezeray::ch09
