// Owen scrambling by hashing (book chapter 09; Owen, "Randomly permuted (t,m,s)-nets and
// (t,s)-sequences", 1995; Laine and Karras, "Stratified sampling for stochastic transparency",
// 2011; Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020).
#pragma once

#include <cstdint>

namespace freezeray::ch09 {

// A permutation of 32-bit words in which bit k of the result depends only on bits 0 to k of x
// (and on the seed): additions and multiplications by even constants carry only upwards. Burley's
// constants (2020, listing 3).
std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed);

// Owen's nested uniform scramble of a 0.32 fraction: each bit is flipped or not according to a
// hash of the bits above it, so the fraction's every dyadic interval [j 2^-m, (j+1) 2^-m) goes
// whole to another one. Points of a (t, m, s)-net stay a (t, m, s)-net; each point alone becomes
// uniform in [0, 1).
std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed);

// The seed of one scramble from several values (Burley 2020's hash_combine, a Boost-style mix).
std::uint32_t hash_combine(std::uint32_t seed, std::uint32_t value);

}  // namespace freezeray::ch09
