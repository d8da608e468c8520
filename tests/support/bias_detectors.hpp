// Bias detectors for grading tests: when a measured mean misses the known answer, name the
// classic mistake whose own (predictable) answer it matches instead. A student told "mean 31.98
// vs known 1" learns that the code is wrong; told "likely mistake: the cosine is missing" learns
// where. Each detector is proven by planting its mistake (tests/grading/planted_mistakes.json).
#pragma once

#include <string>
#include <vector>

namespace freezeray::testing {

// A mistake and the mean an estimator that makes it converges to.
struct Suspect {
    std::string mistake;  // "the cosine |cos theta_i| is missing"
    double predicted;
};

// The suspect whose prediction is nearest `measured`, relatively, if within `tolerance` of it:
// "likely mistake: ... (that would give 32, and this gives 31.98)"; "" when none is.
std::string likely_mistake(double measured, const std::vector<Suspect>& suspects, double tolerance);

// The furnace (tests' scenes/furnace: emission Le and diffuse albedo rho everywhere, paths of at
// most max_depth segments, directions drawn uniformly over the hemisphere as chapter 01 does):
// with a per-bounce weight w whose mean is q, the estimate converges to Le * sum_{k<max_depth} q^k.
// The right weight f |cos| / pdf has q = rho; each mistake its own q: f / pdf (no cosine) 2 rho,
// f |cos| (no 1/pdf) rho / (2 pi), f |cos| / pdf^2 2 pi rho, f |cos| pdf rho / (4 pi^2).
std::vector<Suspect> furnace_suspects(double emitted, double albedo, int max_depth);

}  // namespace freezeray::testing
