// The radical inverse (book chapter 09; Niederreiter, "Random Number Generation and Quasi-Monte
// Carlo Methods", 1992, section 3.1).
#include "freezeray/ch09/radical_inverse.hpp"

#include "freezeray/error.hpp"

namespace freezeray::ch09 {

// BOOK(radical-inverse)
double radical_inverse(std::uint32_t base, std::uint64_t index) {
    // EXERCISE(ch09/radical-inverse): mirror the base-b digits of index about the radix point: the digit of b^k becomes the digit of b^(-k-1)
    const double inverse_base = 1.0 / base;
    double value = 0.0;
    double digit_weight = inverse_base;  // b^(-k-1) for the k-th digit
    while (index > 0) {
        value += static_cast<double>(index % base) * digit_weight;
        index /= base;
        digit_weight *= inverse_base;
    }
    return value;
    // END EXERCISE
}
// END BOOK

std::uint32_t reverse_bits(std::uint32_t x) {
    // Swap halves, then quarters, ... (Warren, "Hacker's Delight", 2nd ed. 2012, section 7-1).
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

}  // namespace freezeray::ch09
