// Bias detectors: the predictions of classic mistakes, and naming the one a measurement matches.
#include "bias_detectors.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace freezeray::testing {

std::string likely_mistake(double measured, const std::vector<Suspect>& suspects, double tolerance) {
    const Suspect* nearest = nullptr;
    double nearest_distance = std::numeric_limits<double>::infinity();
    for (const Suspect& suspect : suspects) {
        const double distance = std::abs(measured - suspect.predicted) / std::max(std::abs(suspect.predicted), 1e-300);
        if (distance < nearest_distance) nearest = &suspect, nearest_distance = distance;
    }
    if (nearest == nullptr || !(nearest_distance <= tolerance)) return "";
    char numbers[128];
    std::snprintf(numbers, sizeof numbers, " (that would give %.4g, and this gives %.4g)", nearest->predicted, measured);
    return "likely mistake: " + nearest->mistake + numbers;
}

std::vector<Suspect> furnace_suspects(double emitted, double albedo, int max_depth) {
    const double pi = 3.14159265358979323846;
    auto estimate = [&](double q) {  // Le * (1 + q + ... + q^(max_depth - 1))
        double sum = 0.0, term = emitted;
        for (int k = 0; k < max_depth; ++k) sum += term, term *= q;
        return sum;
    };
    return {
        {"the cosine |cos theta_i| is missing from the weight (f / pdf)", estimate(2.0 * albedo)},
        {"the weight is not divided by the pdf (f |cos theta_i|)", estimate(albedo / (2.0 * pi))},
        {"the weight is divided by the pdf twice (f |cos theta_i| / pdf^2)", estimate(2.0 * pi * albedo)},
        {"the weight is multiplied by the pdf instead of divided (f |cos theta_i| pdf)", estimate(albedo / (4.0 * pi * pi))},
    };
}

std::string likely_density_mistake(const stats::SampleFunction& sample, const std::vector<DensitySuspect>& suspects,
                                   const stats::ChiSquareOptions& options) {
    for (const DensitySuspect& suspect : suspects) {
        const stats::SampleFunction mapped = [&](PCG32& random) -> std::optional<Vec3> {
            const std::optional<Vec3> drawn = sample(random);
            if (!drawn) return std::nullopt;
            return suspect.coordinates(*drawn);
        };
        const stats::ChiSquareResult fit = stats::chi_square_test(suspect.domain, mapped, suspect.pdf, options);
        if (!fit.passed) continue;
        char p[64];
        std::snprintf(p, sizeof p, " (its samples fit that density: p = %.3g)", fit.p_value);
        return "likely mistake: " + suspect.mistake + p;
    }
    return "";
}

}  // namespace freezeray::testing
