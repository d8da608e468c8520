// Distributions and t-tests. The special functions follow Press, Teukolsky, Vetterling and
// Flannery, "Numerical Recipes", 3rd ed., 2007, chapter 6 (6.2 incomplete gamma, 6.4 incomplete
// beta and the Student and binomial distributions); the normal quantile is Wichura's AS 241.
#include "statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace freezeray::stats {

namespace {

constexpr double relative_epsilon = 1e-15;                             // convergence of the series
constexpr double tiny_number = std::numeric_limits<double>::min() / relative_epsilon;  // Lentz's guard
constexpr int maximum_iterations = 1'000'000;  // series and fractions need O(sqrt(a)) terms

// exp(-x) x^a / Gamma(a): the common factor of P(a, x) and Q(a, x).
double gamma_prefactor(double a, double x) { return std::exp(-x + a * std::log(x) - std::lgamma(a)); }

// P(a, x) by its series, which converges quickly for x < a + 1 (Numerical Recipes 6.2.5).
double gamma_p_by_series(double a, double x) {
    double denominator = a;
    double term = 1.0 / a;
    double sum = term;
    for (int i = 0; i < maximum_iterations; ++i) {
        denominator += 1.0;
        term *= x / denominator;
        sum += term;
        if (std::abs(term) < std::abs(sum) * relative_epsilon) break;
    }
    return sum * gamma_prefactor(a, x);
}

// Q(a, x) by its continued fraction, evaluated with the modified Lentz method; converges quickly
// for x > a + 1 (Numerical Recipes 6.2.7 and 5.2).
double gamma_q_by_continued_fraction(double a, double x) {
    double b = x + 1.0 - a;
    double c = 1.0 / tiny_number;
    double d = 1.0 / b;
    double fraction = d;
    for (int i = 1; i < maximum_iterations; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny_number) d = tiny_number;
        c = b + an / c;
        if (std::abs(c) < tiny_number) c = tiny_number;
        d = 1.0 / d;
        const double step = d * c;
        fraction *= step;
        if (std::abs(step - 1.0) <= relative_epsilon) break;
    }
    return gamma_prefactor(a, x) * fraction;
}

void check_gamma_arguments(double a, double x) {
    if (!(a > 0.0) || !(x >= 0.0)) throw std::invalid_argument("incomplete gamma needs a > 0 and x >= 0");
}

// The continued fraction of I_x(a, b) (Numerical Recipes 6.4.5, modified Lentz method).
double beta_continued_fraction(double a, double b, double x) {
    const double sum_ab = a + b;
    const double a_plus_one = a + 1.0;
    const double a_minus_one = a - 1.0;
    double c = 1.0;
    double d = 1.0 - sum_ab * x / a_plus_one;
    if (std::abs(d) < tiny_number) d = tiny_number;
    d = 1.0 / d;
    double fraction = d;
    for (int m = 1; m < maximum_iterations; ++m) {
        const int m2 = 2 * m;
        double aa = m * (b - m) * x / ((a_minus_one + m2) * (a + m2));  // the even step
        d = 1.0 + aa * d;
        if (std::abs(d) < tiny_number) d = tiny_number;
        c = 1.0 + aa / c;
        if (std::abs(c) < tiny_number) c = tiny_number;
        d = 1.0 / d;
        fraction *= d * c;
        aa = -(a + m) * (sum_ab + m) * x / ((a + m2) * (a_plus_one + m2));  // the odd step
        d = 1.0 + aa * d;
        if (std::abs(d) < tiny_number) d = tiny_number;
        c = 1.0 + aa / c;
        if (std::abs(c) < tiny_number) c = tiny_number;
        d = 1.0 / d;
        const double step = d * c;
        fraction *= step;
        if (std::abs(step - 1.0) <= relative_epsilon) break;
    }
    return fraction;
}

// I_x(a, b) given both x and y = 1 - x, so that neither loses digits when it is close to 1
// (the Student t needs this for large degrees of freedom). Numerical Recipes 6.4.
double incomplete_beta(double a, double b, double x, double y) {
    if (x <= 0.0) return 0.0;
    if (y <= 0.0) return 1.0;
    const double log_x = x > 0.5 ? std::log1p(-y) : std::log(x);
    const double log_y = y > 0.5 ? std::log1p(-x) : std::log(y);
    const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * log_x + b * log_y);
    // The fraction converges fast below the mean (a + 1) / (a + b + 2); above it, use the symmetry
    // I_x(a, b) = 1 - I_{1-x}(b, a).
    if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_continued_fraction(a, b, x) / a;
    return 1.0 - front * beta_continued_fraction(b, a, y) / b;
}

}  // namespace

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

// Wichura, "Algorithm AS 241: The Percentage Points of the Normal Distribution", Applied
// Statistics 37(3), 1988 (PPND16, relative accuracy about 1e-16).
double normal_quantile(double probability) {
    if (!(probability > 0.0 && probability < 1.0)) {
        if (probability == 0.0) return -std::numeric_limits<double>::infinity();
        if (probability == 1.0) return std::numeric_limits<double>::infinity();
        throw std::invalid_argument("normal_quantile needs a probability in [0, 1]");
    }
    const double q = probability - 0.5;
    if (std::abs(q) <= 0.425) {
        const double r = 0.180625 - q * q;
        return q * (((((((2509.0809287301226727 * r + 33430.575583588128105) * r + 67265.770927008700853) * r +
                        45921.953931549871457) * r + 13731.693765509461125) * r + 1971.5909503065514427) * r +
                     133.14166789178437745) * r + 3.3871328727963666080) /
               (((((((5226.4952788528545610 * r + 28729.085735721942674) * r + 39307.895800092710610) * r +
                    21213.794301586595867) * r + 5394.1960214247511077) * r + 687.18700749205790830) * r +
                 42.313330701600911252) * r + 1.0);
    }
    double r = std::sqrt(-std::log(q < 0.0 ? probability : 1.0 - probability));
    double value;
    if (r <= 5.0) {
        r -= 1.6;
        value = (((((((7.74545014278341407640e-4 * r + 2.27238449892691845833e-2) * r + 2.41780725177450611770e-1) * r +
                     1.27045825245236838258) * r + 3.64784832476320460504) * r + 5.76949722146069140550) * r +
                  4.63033784615654529590) * r + 1.42343711074968357734) /
                (((((((1.05075007164441684324e-9 * r + 5.47593808499534494600e-4) * r + 1.51986665636164571966e-2) * r +
                     1.48103976427480074590e-1) * r + 6.89767334985100004550e-1) * r + 1.67638483018380384940) * r +
                  2.05319162663775882187) * r + 1.0);
    } else {
        r -= 5.0;
        value = (((((((2.01033439929228813265e-7 * r + 2.71155556874348757815e-5) * r + 1.24266094738807843860e-3) * r +
                     2.65321895265761230930e-2) * r + 2.96560571828504891230e-1) * r + 1.78482653991729133580) * r +
                  5.46378491116411436990) * r + 6.65790464350110377720) /
                (((((((2.04426310338993978564e-15 * r + 1.42151175831644588870e-7) * r + 1.84631831751005468180e-5) * r +
                     7.86869131145613259100e-4) * r + 1.48753612908506148525e-2) * r + 1.36929880922735805310e-1) * r +
                  5.99832206555887937690e-1) * r + 1.0);
    }
    return q < 0.0 ? -value : value;
}

double regularized_gamma_p(double a, double x) {
    check_gamma_arguments(a, x);
    if (x == 0.0) return 0.0;
    if (x < a + 1.0) return gamma_p_by_series(a, x);
    return 1.0 - gamma_q_by_continued_fraction(a, x);
}

double regularized_gamma_q(double a, double x) {
    check_gamma_arguments(a, x);
    if (x == 0.0) return 1.0;
    if (x < a + 1.0) return 1.0 - gamma_p_by_series(a, x);
    return gamma_q_by_continued_fraction(a, x);
}

// The chi-square distribution with k degrees of freedom is Gamma(k / 2, 2): Numerical Recipes 6.14.
double chi_square_cdf(double x, double degrees_of_freedom) {
    return regularized_gamma_p(0.5 * degrees_of_freedom, 0.5 * std::max(x, 0.0));
}

double chi_square_survival(double x, double degrees_of_freedom) {
    return regularized_gamma_q(0.5 * degrees_of_freedom, 0.5 * std::max(x, 0.0));
}

double regularized_beta(double a, double b, double x) {
    if (!(a > 0.0) || !(b > 0.0) || !(x >= 0.0 && x <= 1.0))
        throw std::invalid_argument("regularized_beta needs a > 0, b > 0 and x in [0, 1]");
    return incomplete_beta(a, b, x, 1.0 - x);
}

// P(|T| >= |t|) = I_{nu / (nu + t^2)}(nu / 2, 1 / 2): Numerical Recipes 6.14.9.
double student_t_two_sided_p_value(double t, double degrees_of_freedom) {
    if (std::isnan(t) || !(degrees_of_freedom > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    if (std::isinf(degrees_of_freedom)) return 2.0 * normal_cdf(-std::abs(t));
    if (std::isinf(t)) return 0.0;
    const double t_squared = t * t;
    const double x = degrees_of_freedom / (degrees_of_freedom + t_squared);
    const double y = t_squared / (degrees_of_freedom + t_squared);
    return incomplete_beta(0.5 * degrees_of_freedom, 0.5, x, y);
}

double student_t_survival(double t, double degrees_of_freedom) {
    const double two_sided = student_t_two_sided_p_value(t, degrees_of_freedom);
    return t > 0.0 ? 0.5 * two_sided : 1.0 - 0.5 * two_sided;
}

double student_t_cdf(double t, double degrees_of_freedom) { return student_t_survival(-t, degrees_of_freedom); }

// P(X >= k) = I_p(k, n - k + 1): Numerical Recipes 6.14.15.
double binomial_survival(std::int64_t k, std::int64_t trials, double probability) {
    if (k <= 0) return 1.0;
    if (k > trials) return 0.0;
    if (probability <= 0.0) return 0.0;
    if (probability >= 1.0) return 1.0;
    return incomplete_beta(static_cast<double>(k), static_cast<double>(trials - k + 1), probability, 1.0 - probability);
}

std::int64_t binomial_critical_count(std::int64_t trials, double probability, double alpha) {
    // P(X > c) falls as c grows and is 0 at c = trials: bisect for the first c where it is <= alpha.
    std::int64_t low = 0;
    std::int64_t high = trials;
    while (low < high) {
        const std::int64_t middle = low + (high - low) / 2;
        if (binomial_survival(middle + 1, trials, probability) <= alpha)
            high = middle;
        else
            low = middle + 1;
    }
    return low;
}

double sidak_alpha(double alpha, std::size_t test_count) {
    if (test_count == 0) return alpha;
    // 1 - (1 - alpha)^(1/m), written with log1p and expm1 so that tiny levels keep their digits.
    return -std::expm1(std::log1p(-alpha) / static_cast<double>(test_count));
}

double normal_test_power(double shift_in_standard_errors, double alpha) {
    const double critical = normal_quantile(1.0 - 0.5 * alpha);
    const double shift = std::abs(shift_in_standard_errors);
    return normal_cdf(shift - critical) + normal_cdf(-shift - critical);
}

MeanEstimate estimate_mean(std::span<const double> values) {
    if (values.size() < 2) throw std::invalid_argument("estimate_mean needs at least two values");
    const double n = static_cast<double>(values.size());
    double sum = 0.0;
    for (double v : values) sum += v;
    const double mean = sum / n;
    double squared_deviations = 0.0;  // two passes: exact enough and simple
    for (double v : values) squared_deviations += (v - mean) * (v - mean);
    const double sample_variance = squared_deviations / (n - 1.0);
    return {mean, sample_variance / n, n - 1.0};
}

std::string format_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

namespace {

// True when two exact answers agree up to float rounding (zero_variance_relative_tolerance).
bool equal_within_rounding(double first, double second) {
    return std::abs(first - second) <= zero_variance_relative_tolerance * std::max(std::abs(first), std::abs(second));
}

// The verdict when the variance of a difference is zero: no noise, so the means must agree.
TestResult zero_variance_verdict(double first, double second, const std::string& what) {
    TestResult result;
    result.passed = equal_within_rounding(first, second);
    result.p_value = result.passed ? 1.0 : 0.0;
    result.statistic = result.passed ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), first - second);
    result.message = what + ": " + format_number(first) + " vs " + format_number(second) +
                     " with zero variance: " + (result.passed ? "equal, passed" : "different, FAILED");
    return result;
}

TestResult invalid_input_verdict(const std::string& what) {
    TestResult result;
    result.passed = false;
    result.p_value = 0.0;
    result.statistic = std::numeric_limits<double>::quiet_NaN();
    result.message = what + ": a mean or variance is NaN, infinite or negative, FAILED";
    return result;
}

bool is_valid(const MeanEstimate& e) {
    return std::isfinite(e.mean) && std::isfinite(e.variance_of_mean) && e.variance_of_mean >= 0.0;
}

// Welch–Satterthwaite: dof = (v1 + v2)^2 / (v1^2 / dof1 + v2^2 / dof2); a side without variance
// contributes nothing. The variance v1 + v2 must be positive.
double welch_degrees_of_freedom(const MeanEstimate& first, const MeanEstimate& second) {
    const double variance = first.variance_of_mean + second.variance_of_mean;
    double denominator = 0.0;
    for (const MeanEstimate* side : {&first, &second}) {
        if (side->variance_of_mean == 0.0) continue;
        if (!(side->degrees_of_freedom > 0.0))
            throw std::invalid_argument("welch_t_test: a non-zero variance needs degrees of freedom > 0");
        denominator += side->variance_of_mean * side->variance_of_mean / side->degrees_of_freedom;
    }
    return variance * variance / denominator;
}

TestResult t_verdict(double t, double degrees_of_freedom, double alpha, const std::string& comparison) {
    TestResult result;
    result.statistic = t;
    result.degrees_of_freedom = degrees_of_freedom;
    result.p_value = student_t_two_sided_p_value(t, degrees_of_freedom);
    result.passed = result.p_value > alpha;
    result.message = comparison + ", t = " + format_number(t) + ", dof " + format_number(degrees_of_freedom) +
                     ", p = " + format_number(result.p_value) + (result.passed ? " > " : " <= ") + "alpha " +
                     format_number(alpha) + (result.passed ? ": passed" : ": FAILED");
    return result;
}

}  // namespace

TestResult one_sample_t_test(const MeanEstimate& estimate, double known_value, double alpha) {
    const std::string what = "one-sample t-test, mean " + format_number(estimate.mean) + " vs known " +
                             format_number(known_value);
    if (!is_valid(estimate) || !std::isfinite(known_value)) return invalid_input_verdict(what);
    if (estimate.variance_of_mean == 0.0) return zero_variance_verdict(estimate.mean, known_value, "one-sample t-test");
    if (!(estimate.degrees_of_freedom > 0.0))
        throw std::invalid_argument("one_sample_t_test: a non-zero variance needs degrees of freedom > 0");
    const double t = (estimate.mean - known_value) / std::sqrt(estimate.variance_of_mean);
    return t_verdict(t, estimate.degrees_of_freedom, alpha, what);
}

TestResult one_sample_t_test(std::span<const double> values, double known_value, double alpha) {
    return one_sample_t_test(estimate_mean(values), known_value, alpha);
}

TestResult welch_t_test(const MeanEstimate& first, const MeanEstimate& second, double alpha) {
    const std::string what = "Welch t-test, means " + format_number(first.mean) + " vs " + format_number(second.mean);
    if (!is_valid(first) || !is_valid(second)) return invalid_input_verdict(what);
    const double variance = first.variance_of_mean + second.variance_of_mean;
    if (variance == 0.0) return zero_variance_verdict(first.mean, second.mean, "Welch t-test");
    const double t = (first.mean - second.mean) / std::sqrt(variance);
    return t_verdict(t, welch_degrees_of_freedom(first, second), alpha, what);
}

double welch_p_value(const MeanEstimate& first, const MeanEstimate& second) {
    if (!is_valid(first) || !is_valid(second)) return 0.0;
    const double variance = first.variance_of_mean + second.variance_of_mean;
    if (variance == 0.0) return equal_within_rounding(first.mean, second.mean) ? 1.0 : 0.0;
    const double t = (first.mean - second.mean) / std::sqrt(variance);
    return student_t_two_sided_p_value(t, welch_degrees_of_freedom(first, second));
}

TestResult welch_t_test(double mean1, double variance_of_mean1, double n1, double mean2, double variance_of_mean2,
                        double n2, double alpha) {
    return welch_t_test(MeanEstimate{mean1, variance_of_mean1, n1 - 1.0}, MeanEstimate{mean2, variance_of_mean2, n2 - 1.0},
                        alpha);
}

}  // namespace freezeray::stats
