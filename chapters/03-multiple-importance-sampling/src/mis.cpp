// MIS heuristics (Veach 1997, chapter 9).
#include "freezeray/ch03/mis.hpp"

namespace freezeray::ch03 {

// Both heuristics are written with the ratio g / f, which stays finite where f^2 + g^2 would
// overflow (a tiny light seen from far away has a solid-angle density beyond 1e19).
float balance_heuristic(int n_f, float pdf_f, int n_g, float pdf_g) {
    const float f = static_cast<float>(n_f) * pdf_f, g = static_cast<float>(n_g) * pdf_g;
    if (!(f > 0.0f)) return 0.0f;
    return 1.0f / (1.0f + g / f);
}

// BOOK(power-heuristic)
float power_heuristic(int n_f, float pdf_f, int n_g, float pdf_g) {
    const float f = static_cast<float>(n_f) * pdf_f, g = static_cast<float>(n_g) * pdf_g;
    // EXERCISE(ch03/power-heuristic): the weight of strategy f against strategy g by Veach's power heuristic with exponent 2, book chapter 03, "Multiple importance sampling"
    if (!(f > 0.0f)) return 0.0f;
    const float ratio = g / f;
    return 1.0f / (1.0f + ratio * ratio);
    // END EXERCISE
}
// END BOOK

}  // namespace freezeray::ch03
