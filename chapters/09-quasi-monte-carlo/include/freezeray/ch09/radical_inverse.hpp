// The radical inverse: the digits of an index mirrored about the radix point (book chapter 09).
// In base 2 it is the van der Corput sequence, 0, 1/2, 1/4, 3/4, 1/8, ...; in the first s prime
// bases it gives the s-dimensional Halton sequence (Halton 1960).
#pragma once

#include <cstdint>

namespace freezeray::ch09 {

// Phi_b(i) = sum_k d_k b^(-k-1) for i = sum_k d_k b^k (base b >= 2), in [0, 1).
double radical_inverse(std::uint32_t base, std::uint64_t index);

// The 32 bits of `x` in the opposite order: the base-2 radical inverse of x as a 0.32 fixed-point
// fraction (bit 31 of the result is bit 0 of x).
// Inline: a sampler reverses bits several times per draw. A byte swap, then nibbles, pairs and
// bits (Warren, "Hacker's Delight", 2nd ed. 2012, section 7-1).
inline std::uint32_t reverse_bits(std::uint32_t x) {
    x = __builtin_bswap32(x);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

}  // namespace freezeray::ch09
