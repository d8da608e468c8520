// Whether renders of one scene agree within their own noise: how `auto` (chapter 05) and the
// comparison's report (book chapter 00) tell a render that has not converged from one that has.
#pragma once

#include "freezeray/integrator.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace freezeray {

// Whether two renders of the same scene agree within their noise. For independent unbiased
// renders a and b, E[(a - b)^2] = Var a + Var b in every pixel and channel, so the relMSE between
// them should be the sum of their own estimated relMSEs: with weights w = 1 / (m^2 + 0.01) (m
// their mean, as relMSE weighs pixels), D = sum w (a - b)^2 / sum w (Var a + Var b) is about 1.
// Ratios of sums, not a mean of per-pixel ratios, because a splatting film's per-pixel variance
// is a noisy one-degree-of-freedom estimate. A D well above 1 says that at least one of them has
// not converged (rare bright paths not yet found, or bias). Pixel-channels where both variances
// are zero are counted apart: `one_sided` those that differ there (lit in one render, and black
// with zero variance in the other: light one of them has not found).
struct Agreement {
    double statistic = 0.0;        // D
    double standard_error = 0.0;   // of D's numerator and denominator together, relative, if they agree
    std::size_t terms = 0;         // pixel-channels with a variance
    std::size_t one_sided = 0;     // pixel-channels that differ where both variances are zero
    // D beyond 1 + 6 standard errors, or any one-sided pixel.
    bool disagree() const;
};
Agreement agreement(const RenderResult& a, const RenderResult& b);

// The agreement of renders `first` and `second` (indices into the renders compared).
struct RunAgreement {
    std::size_t first = 0, second = 0;
    Agreement agreement;
};

// Every pair of renders (in index order) whose images have variances to compare with.
std::vector<RunAgreement> pairwise_agreements(const std::vector<const RenderResult*>& results);

// Which run has not converged: the one that disagrees with every other, each time by at least
// OddOneOutRatio times as much (D - 1) as any two of the others disagree among themselves (zero
// when they agree), so at least three runs. A run that has missed some light disagrees with all
// who found it; runs that found it disagree among themselves only by their estimates' own
// shortfalls, which at a few samples per pixel are not zero. None when no run stands out.
inline constexpr double OddOneOutRatio = 2.0;
std::optional<std::size_t> odd_one_out(const std::vector<RunAgreement>& agreements, std::size_t runs);

}  // namespace freezeray
