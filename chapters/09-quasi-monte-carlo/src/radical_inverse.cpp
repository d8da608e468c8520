// The radical inverse (book chapter 09; Niederreiter, "Random Number Generation and Quasi-Monte
// Carlo Methods", 1992, section 3.1).
#include "freezeray/ch09/radical_inverse.hpp"

#include "freezeray/error.hpp"

namespace freezeray::ch09 {

// BOOK(radical-inverse)
double radical_inverse(std::uint32_t base, std::uint64_t index) {
    // EXERCISE(ch09/radical-inverse): the radical inverse of index in base b, book chapter 09, "The radical inverse"
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

}  // namespace freezeray::ch09
