// Owen scrambling by hashing (book chapter 09; Owen, "Randomly permuted (t,m,s)-nets and
// (t,s)-sequences", 1995; Laine and Karras, "Stratified sampling for stochastic transparency",
// 2011; Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020).
#pragma once

#include "freezeray/ch09/radical_inverse.hpp"

#include <cstdint>

namespace freezeray::ch09 {

// A hash of 32-bit words, keyed by the seed, that is Owen's nested scramble of the word read
// from bit 0 up (nested_uniform_scramble applies it to reversed bits). The contract:
// - bit k of the result depends only on bits 0 to k of x (and on the seed): two words that agree
//   in their low k + 1 bits have images that agree in them too;
// - for every seed it is a bijection, and so a bijection of the low k bits for every k: the
//   2^k words below 2^k have 2^k different low k bits;
// - bit k is x's bit k flipped or not by a coin that the seed and bits 0 to k - 1 toss: for two
//   words that first differ at bit j, each higher bit k of their images differs for about half of
//   the seeds (Owen's coins are fair and independent; this family of hashes comes close, roughly
//   30 to 75 percent for every j < k, where a sum or a product alone stays near 0 or 1);
// - different seeds give different permutations.
// Laine and Karras (2011) build it from operations that carry only upwards (additions, and
// multiplications by even constants XORed in); Burley (2020) gives constants that make it
// good. Inline, like the scramble below: a sampler calls it several times per draw.
inline std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
    // EXERCISE(ch09/owen-hash): the hash of book chapter 09, "Why scrambling", that makes Owen's nested scramble practical, as laine_karras_permutation's comment states its contract (bits carried only upwards, a bijection, coins tossed by the seed and the lower bits); see Laine and Karras 2011 and Burley 2020
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
    // END EXERCISE
}

// Owen's nested uniform scramble of a 0.32 fraction: each bit is flipped or not according to a
// hash of the bits above it, so the fraction's every dyadic interval [j 2^-m, (j+1) 2^-m) goes
// whole to another one. Points of a (t, m, s)-net stay a (t, m, s)-net; each point alone becomes
// uniform in [0, 1).
// BOOK(owen-scramble)
inline std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed) {
    // Reversed, the fraction's most significant bit is bit 0, on which every other bit of the
    // permutation may depend: bit k of the fraction is flipped by a function of the bits above it.
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}
// END BOOK

// The seed of one scramble from several values (Burley 2020's hash_combine, a Boost-style mix).
inline std::uint32_t hash_combine(std::uint32_t seed, std::uint32_t value) {
    return seed ^ (value + 0x9e3779b9u + (seed << 6) + (seed >> 2));
}

}  // namespace freezeray::ch09
