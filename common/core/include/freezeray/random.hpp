// PCG32 random streams, seeded from (seed, pixel, sample) so that images are reproducible
// whatever the number of threads.
#pragma once

#include <cstdint>

namespace freezeray {

// The PCG32 generator (XSH-RR output on a 64-bit LCG): O'Neill, "PCG: A Family of Simple Fast
// Space-Efficient Statistically Good Algorithms for Random Number Generation", 2014.
class PCG32 {
public:
    PCG32() { seed(0x853c49e6748fea9bULL, 0xda3e39cb94b95bdbULL); }
    PCG32(std::uint64_t initial_state, std::uint64_t stream) { seed(initial_state, stream); }

    void seed(std::uint64_t initial_state, std::uint64_t stream) {
        state_ = 0;
        increment_ = (stream << 1u) | 1u;
        next_uint();
        state_ += initial_state;
        next_uint();
    }

    std::uint32_t next_uint() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + increment_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rotation = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rotation) | (xorshifted << ((~rotation + 1u) & 31u));
    }

    // Uniform float in [0, 1): the top 24 bits, so every value is exactly representable and < 1.
    float next_float() { return static_cast<float>(next_uint() >> 8) * 0x1p-24f; }

    // Uniform double in [0, 1) from 53 random bits.
    double next_double() {
        const std::uint64_t bits = (static_cast<std::uint64_t>(next_uint()) << 21) ^ next_uint();
        return static_cast<double>(bits & ((1ULL << 53) - 1)) * 0x1p-53;
    }

    // Uniform integer in [0, bound) without modulo bias (rejection of the short top interval).
    std::uint32_t next_below(std::uint32_t bound) {
        const std::uint32_t threshold = (~bound + 1u) % bound;
        for (;;) {
            const std::uint32_t r = next_uint();
            if (r >= threshold) return r % bound;
        }
    }

private:
    std::uint64_t state_ = 0;
    std::uint64_t increment_ = 0;
};

// A 64-bit mixing function (the finaliser of SplitMix64, Steele, Lea and Flood 2014) used to
// turn structured keys such as (seed, pixel, sample) into well-spread PCG seeds.
inline std::uint64_t mix_bits(std::uint64_t v) {
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ULL;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebULL;
    v ^= v >> 31;
    return v;
}

// A 64-bit key for one pixel of a render with this seed. `salt` keeps apart the keys of different
// users (the independent sampler, chapter 09's samplers), so that their numbers are unrelated.
inline std::uint64_t pixel_key(std::uint64_t seed, std::uint32_t pixel_index, std::uint64_t salt) {
    return mix_bits(seed ^ mix_bits((static_cast<std::uint64_t>(pixel_index) << 32) ^ salt));
}

// A uniform float in [0, 1) that depends only on `key`: the first number of a PCG32 stream it
// seeds. For numbers addressed by (pixel, sample, dimension) rather than drawn in sequence.
inline float hashed_uniform(std::uint64_t key) {
    PCG32 random(key, 0x14057b7ef767814fULL);
    return random.next_float();
}

// The stream for one sample of one pixel. Every random number of that sample comes from it,
// so a pixel's value never depends on which thread rendered it or in which order.
inline PCG32 make_pixel_stream(std::uint64_t seed, std::uint32_t pixel_index, std::uint64_t sample_index) {
    const std::uint64_t key = pixel_key(seed, pixel_index, 0x9e3779b97f4a7c15ULL);
    return PCG32(mix_bits(key + sample_index), key);
}

// The stream for an independent chain or job (Markov chains, light paths, test cases).
inline PCG32 make_chain_stream(std::uint64_t seed, std::uint64_t chain_index) {
    return PCG32(mix_bits(seed * 0x9e3779b97f4a7c15ULL + chain_index), mix_bits(chain_index ^ 0x632be59bd9b4e019ULL));
}

}  // namespace freezeray
