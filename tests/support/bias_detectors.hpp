// Bias detectors for grading tests: when a measured mean misses the known answer, name the
// classic mistake whose own (predictable) answer it matches instead. A student told "mean 31.98
// vs known 1" learns that the code is wrong; told "likely mistake: the cosine is missing" learns
// where. Each detector is proven by planting its mistake (tests/grading/planted_mistakes.json).
#pragma once

#include "chi_square.hpp"

#include <functional>
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

// A mistaken sampling routine draws from some other density: a suspect is a mistake and the
// density it gives, on a domain of its choice: the samples are mapped into it first, so that a
// density singular in one parametrisation can be tested where it is smooth (theta uniform in
// [0, pi/2] is 1 / (pi^2 sin theta) per solid angle, but 2 / pi per unit of theta).
struct DensitySuspect {
    std::string mistake;  // "theta uniform in [0, pi/2] instead of cos theta uniform in [0, 1]"
    stats::Domain domain;
    std::function<Vec3(const Vec3&)> coordinates;  // a sample's point in `domain`
    stats::DensityFunction pdf;                    // the mistake's density there
};

// For a sampler that failed its chi-square test: the first suspect whose density its samples pass
// the test against (same sample count, cells and false-failure rate), named: "likely mistake:
// ... (its samples fit that density: p = 0.41)"; "" when none fits.
std::string likely_density_mistake(const stats::SampleFunction& sample, const std::vector<DensitySuspect>& suspects,
                                   const stats::ChiSquareOptions& options);

}  // namespace freezeray::testing
