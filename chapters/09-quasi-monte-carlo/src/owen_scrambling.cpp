// Owen scrambling by hashing (book chapter 09; Burley 2020).
#include "freezeray/ch09/owen_scrambling.hpp"

#include "freezeray/ch09/radical_inverse.hpp"

namespace freezeray::ch09 {

std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// BOOK(owen-scramble)
std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed) {
    // Reversed, the fraction's most significant bit is bit 0, on which every other bit of the
    // permutation may depend: bit k of the fraction is flipped by a function of the bits above it.
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}
// END BOOK

std::uint32_t hash_combine(std::uint32_t seed, std::uint32_t value) {
    return seed ^ (value + 0x9e3779b9u + (seed << 6) + (seed >> 2));
}

}  // namespace freezeray::ch09
