// Chapter 09's claim in numbers: integrating 2-D functions with a sampler's draws, the error of
// the stratified and Sobol samplers falls faster than independent sampling's 1/N, and every
// sampler stays unbiased. Each pixel of a 2048-pixel "image" is one independent replicate (its
// scrambles are its own); the replicates are split into 16 groups, each group gives a fitted
// slope of log MSE against log N over N = 2, 4, ..., 1024, and the 16 slopes give a confidence
// interval. Nine statistical tests, each at unit_test_alpha (tests/STATISTICS.md, label unit):
// five on slopes, four t-tests of the mean.
#include "freezeray/ch09/sobol_sampler.hpp"
#include "freezeray/ch09/stratified_sampler.hpp"
#include "freezeray/comparison.hpp"
#include "freezeray/sampler.hpp"

#include "statistics.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <vector>

using namespace freezeray;

namespace {

constexpr int Groups = 16;
constexpr int PixelsPerGroup = 128;
constexpr int LogMaxSamples = 10;  // N up to 1024

using Integrand = std::function<double(double, double)>;

// A smooth function, f = e^u (1 + v^2): integral (e - 1) 4/3.
double smooth(double u, double v) { return std::exp(u) * (1.0 + v * v); }
const double smooth_integral = (std::numbers::e - 1.0) * 4.0 / 3.0;
// A discontinuous one, the quarter disc u^2 + v^2 < 1: integral pi / 4.
double disc(double u, double v) { return u * u + v * v < 1.0 ? 1.0 : 0.0; }
const double disc_integral = std::numbers::pi / 4.0;

struct Measurement {
    std::vector<double> group_slopes;
    std::vector<double> estimates_at_64;  // one per pixel: the mean of its first 64 samples
};

// Integrates f with vertex 1's BSDF-direction draws of every pixel's first 2^k samples.
Measurement measure(Sampler& sampler, const Integrand& f, double integral) {
    sampler.set_seed(2024);
    Measurement result;
    for (int g = 0; g < Groups; ++g) {
        std::vector<double> squared_error(LogMaxSamples + 1, 0.0);
        for (int p = 0; p < PixelsPerGroup; ++p) {
            const auto pixel = static_cast<std::uint32_t>(g * PixelsPerGroup + p);
            double sum = 0.0;
            for (std::uint64_t i = 0; i < (std::uint64_t{1} << LogMaxSamples); ++i) {
                sampler.start_pixel_sample(static_cast<int>(pixel % 64), static_cast<int>(pixel / 64), pixel, i);
                sampler.start_vertex(1);
                const Vec2 u = sampler.get_2d(VertexDimension::BsdfDirection);
                sum += f(u.x, u.y);
                const std::uint64_t n = i + 1;
                if ((n & (n - 1)) == 0) {  // n = 2^k
                    const double error = sum / static_cast<double>(n) - integral;
                    squared_error[static_cast<std::size_t>(std::countr_zero(n))] += error * error;
                    if (n == 64) result.estimates_at_64.push_back(sum / 64.0);
                }
            }
        }
        std::vector<double> log_n, log_mse;
        for (int k = 1; k <= LogMaxSamples; ++k) {
            log_n.push_back(k * std::log(2.0));
            log_mse.push_back(std::log(squared_error[static_cast<std::size_t>(k)] / PixelsPerGroup));
        }
        result.group_slopes.push_back(fit_line(log_n, log_mse).slope);
    }
    return result;
}

// The mean of the group slopes and the one-sided bound below which the true slope lies with
// probability 1 - unit_test_alpha (Student's t with Groups - 1 degrees of freedom).
struct SlopeBound {
    double mean = 0.0, standard_error = 0.0, upper = 0.0;
};
SlopeBound slope_bound(const std::vector<double>& slopes) {
    const auto n = static_cast<double>(slopes.size());
    double mean = 0.0;
    for (double s : slopes) mean += s / n;
    double variance = 0.0;
    for (double s : slopes) variance += (s - mean) * (s - mean) / (n - 1.0);
    double lo = 0.0, hi = 1000.0;  // the t with P(T > t) = alpha, by bisection
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (stats::student_t_survival(mid, n - 1.0) > stats::unit_test_alpha ? lo : hi) = mid;
    }
    const double se = std::sqrt(variance / n);
    return {mean, se, mean + hi * se};
}

}  // namespace

TEST_CASE("independent sampling's MSE falls like 1/N; stratified and Sobol faster on a smooth integrand",
          "[unit][ch09][statistical]") {
    IndependentSampler independent;
    ch09::StratifiedSampler stratified;
    ch09::SobolSampler sobol;

    const Measurement m_independent = measure(independent, smooth, smooth_integral);
    const stats::TestResult minus_one = stats::one_sample_t_test(m_independent.group_slopes, -1.0, stats::unit_test_alpha);
    INFO("independent: " << minus_one.message);
    CHECK(minus_one.passed);

    // Theory for these f (Owen, "Scrambled net variance for integrals of smooth functions", Annals
    // of Statistics 25, 1997): O(N^-3 log N) for a scrambled net; jittered sampling in 2-D,
    // O(N^-2). The tests claim only what the chapter does: faster than N^-1.5.
    const SlopeBound b_stratified = slope_bound(measure(stratified, smooth, smooth_integral).group_slopes);
    INFO("stratified slope " << b_stratified.mean << " +- " << b_stratified.standard_error);
    CHECK(b_stratified.upper < -1.5);
    const SlopeBound b_sobol = slope_bound(measure(sobol, smooth, smooth_integral).group_slopes);
    INFO("sobol slope " << b_sobol.mean << " +- " << b_sobol.standard_error);
    CHECK(b_sobol.upper < -1.5);
}

TEST_CASE("on a discontinuous integrand stratified and Sobol still beat 1/N, without bias", "[unit][ch09][statistical]") {
    // A discontinuity along a curve: O(N^-1.5) for both (Owen 1997; Mitchell, "Consequences of
    // stratified sampling in graphics", SIGGRAPH 1996). The tests claim faster than N^-1.25, and
    // that the 2048 independent 64-sample estimates' mean is the exact integral (two-sided t-tests).
    ch09::StratifiedSampler stratified;
    ch09::SobolSampler sobol;
    for (Sampler* s : {static_cast<Sampler*>(&stratified), static_cast<Sampler*>(&sobol)}) {
        const Measurement m = measure(*s, disc, disc_integral);
        const SlopeBound b = slope_bound(m.group_slopes);
        INFO((s == &sobol ? "sobol" : "stratified") << " slope " << b.mean << " +- " << b.standard_error);
        CHECK(b.upper < -1.25);
        const stats::TestResult unbiased = stats::one_sample_t_test(m.estimates_at_64, disc_integral, stats::unit_test_alpha);
        INFO(unbiased.message);
        CHECK(unbiased.passed);
        const Measurement smooth_m = measure(*s, smooth, smooth_integral);
        const stats::TestResult smooth_unbiased =
            stats::one_sample_t_test(smooth_m.estimates_at_64, smooth_integral, stats::unit_test_alpha);
        INFO(smooth_unbiased.message);
        CHECK(smooth_unbiased.passed);
    }
}
