// Multiple importance sampling weights (Veach and Guibas, "Optimally Combining Sampling
// Techniques for Monte Carlo Rendering", SIGGRAPH 1995; Veach's thesis 1997, chapter 9).
#pragma once

namespace freezeray::ch03 {

// The balance heuristic: w_f = n_f p_f / (n_f p_f + n_g p_g) (Veach 1997, eq. 9.4).
float balance_heuristic(int n_f, float pdf_f, int n_g, float pdf_g);

// The power heuristic with exponent 2: w_f = (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2)
// (Veach 1997, eq. 9.13).
float power_heuristic(int n_f, float pdf_f, int n_g, float pdf_g);

enum class MisHeuristic { Power, Balance };

inline float mis_weight(MisHeuristic heuristic, float pdf_f, float pdf_g) {
    return heuristic == MisHeuristic::Power ? power_heuristic(1, pdf_f, 1, pdf_g) : balance_heuristic(1, pdf_f, 1, pdf_g);
}

}  // namespace freezeray::ch03
