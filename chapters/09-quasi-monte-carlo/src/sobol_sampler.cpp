// The Owen-scrambled Sobol sampler (book chapter 09; Burley 2020, section 4).
#include "freezeray/ch09/sobol_sampler.hpp"

#include "freezeray/ch09/fixed_point.hpp"
#include "freezeray/ch09/owen_scrambling.hpp"
#include "freezeray/ch09/radical_inverse.hpp"
#include "freezeray/ch09/scrambled_sobol.hpp"
#include "freezeray/random.hpp"

namespace freezeray::ch09 {

void SobolSampler::begin(int, int, std::uint32_t pixel_index, std::uint64_t sample_index) {
    if (pixel_stamp_ == 0 || pixel_index != last_pixel_index_ || seed() != last_seed_) {
        pixel_key_ = pixel_key(seed(), pixel_index, 0x5851f42d4c957f2dULL);
        last_pixel_index_ = pixel_index;
        last_seed_ = seed();
        ++pixel_stamp_;  // every dimension's key is stale
    }
    sample_index_ = sample_index;
    reversed_sample_index_ = reverse_bits(static_cast<std::uint32_t>(sample_index));
    ++sample_stamp_;
}

std::uint64_t SobolSampler::dimension_key(std::uint32_t dimension) {
    if (dimension >= QuasiRandomDimensions) return mix_bits(pixel_key_ + dimension);
    DimensionKey& cached = keys_[dimension];
    if (cached.stamp != pixel_stamp_) {
        cached.key = mix_bits(pixel_key_ + dimension);
        cached.stamp = pixel_stamp_;
    }
    return cached.key;
}

float SobolSampler::hashed_random(std::uint32_t dimension) {
    return hashed_uniform(mix_bits(dimension_key(dimension) ^ mix_bits(sample_index_)));
}

// BOOK(sobol-sampler)
std::uint32_t SobolSampler::reversed_shuffled_index(std::uint32_t set) {
    ShuffledIndex& shuffled = shuffled_[set];
    if (shuffled.stamp != sample_stamp_) {
        // The index shuffled by a nested scramble: the samples a 2^m to (a + 1) 2^m - 1 of a pixel
        // become, up to a digital shift, the sequence's first 2^m points in another order, a
        // (0, m, 2)-net. Indices past 2^32 wrap (4 billion samples of one pixel). This is
        // nested_uniform_scramble(index, seed) without its last reversal, which the draws
        // (scrambled_sobol_coordinate) do not need. All draws of a set take the same index,
        // computed once per sample.
        const auto seed = static_cast<std::uint32_t>(dimension_key(set));
        shuffled.reversed_index = laine_karras_permutation(reversed_sample_index_, seed);
        shuffled.stamp = sample_stamp_;
    }
    return shuffled.reversed_index;
}

float SobolSampler::sample_1d(const Draw& draw) {
    const DrawPlace place = draw_place(draw);
    if (place.dimension >= QuasiRandomDimensions) return hashed_random(place.dimension);
    const std::uint32_t index = reversed_shuffled_index(place.set);
    // Each draw its own scramble, seeded by its dimension.
    const auto scramble_seed = static_cast<std::uint32_t>(dimension_key(place.dimension) >> 32);
    return fraction_to_float(scrambled_sobol_coordinate(tables_, index, place.coordinate, scramble_seed));
}

Vec2 SobolSampler::sample_2d(const Draw& draw) {
    const DrawPlace place = draw_place(draw);
    if (place.dimension + 1 >= QuasiRandomDimensions)
        return Vec2(hashed_random(place.dimension), hashed_random(place.dimension + 1));
    const std::uint32_t index = reversed_shuffled_index(place.set);
    const auto scramble_seed = static_cast<std::uint32_t>(dimension_key(place.dimension) >> 32);
    return scrambled_sobol_pair(tables_, index, place.coordinate, scramble_seed);
}
// END BOOK

}  // namespace freezeray::ch09
