// The Metropolis-Hastings rules (book chapter 05).
#include "freezeray/ch05/metropolis.hpp"

#include "freezeray/math.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch05 {

// BOOK(acceptance-probability)
float acceptance_probability(float current, float proposed) {
    // EXERCISE(ch05/acceptance-probability): return min(1, proposed / current), and 1 when the current value is not positive
    if (!(current > 0.0f)) return 1.0f;
    return std::min(1.0f, proposed / current);
    // END EXERCISE
}
// END BOOK

// BOOK(small-step)
float small_step(float value, float normal_sample, float sigma, std::uint64_t steps) {
    // EXERCISE(ch05/small-step): add normal_sample times sigma times the square root of steps, then wrap the result into [0, 1)
    const float moved = value + normal_sample * sigma * std::sqrt(static_cast<float>(steps));
    const float wrapped = moved - std::floor(moved);
    return std::min(wrapped, OneMinusEpsilon);  // -1e-9 wraps to 1 - 1e-9, which rounds to 1
    // END EXERCISE
}
// END BOOK

}  // namespace freezeray::ch05
