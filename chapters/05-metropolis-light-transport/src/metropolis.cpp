// The Metropolis-Hastings rules (book chapter 05).
#include "freezeray/ch05/metropolis.hpp"

#include "freezeray/math.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch05 {

// BOOK(acceptance-probability)
float acceptance_probability(float current, float proposed) {
    // EXERCISE(ch05/acceptance-probability): the Metropolis-Hastings acceptance probability for a symmetric proposal, book chapter 05, "The Metropolis–Hastings rule", including what happens when the current state has no value
    if (!(current > 0.0f)) return 1.0f;
    return std::min(1.0f, proposed / current);
    // END EXERCISE
}
// END BOOK

// BOOK(small-step)
float small_step(float value, float normal_sample, float sigma, std::uint64_t steps) {
    // EXERCISE(ch05/small-step): perturb one primary sample coordinate as the small step of book chapter 05, "Mutations: small and large steps", describes it (a normal step whose spread grows with the steps skipped), staying in [0, 1)
    const float moved = value + normal_sample * sigma * std::sqrt(static_cast<float>(steps));
    const float wrapped = moved - std::floor(moved);
    return std::min(wrapped, OneMinusEpsilon);  // -1e-9 wraps to 1 - 1e-9, which rounds to 1
    // END EXERCISE
}
// END BOOK

}  // namespace freezeray::ch05
