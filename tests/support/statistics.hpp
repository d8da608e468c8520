// Distributions and hypothesis tests for the test suite: the normal, chi-square, Student t and
// binomial distributions, the Šidák correction, and the one- and two-sample t-tests.
// Every statistical test in tests/ is built from these; tests/STATISTICS.md says how to use them
// and how each test's false-failure rate fits the suite's budget.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace freezeray::stats {

// --- The suite's false-failure budget (tests/STATISTICS.md, "Budget") ---------------------------
// A correct renderer fails the default test run with probability at most 1e-3 (union bound over
// all statistical tests). Each test takes the level of its label; the table in STATISTICS.md
// says how many tests each label may hold before its share is spent.
inline constexpr double suite_false_failure_budget = 1e-3;
inline constexpr double chi_square_test_alpha = 1e-6;   // label chi2: up to 400 tests
inline constexpr double convergence_test_alpha = 2.5e-6;  // label convergence: up to 160 tests
inline constexpr double exercise_test_alpha = 1e-6;     // label exercise: up to 100 tests
inline constexpr double unit_test_alpha = 1e-6;         // label unit: up to 50 tests

// --- Distributions --------------------------------------------------------------------------------

// The standard normal cumulative distribution function Phi(x) = P(Z <= x), accurate in both tails.
double normal_cdf(double x);

// The inverse of normal_cdf: the x with Phi(x) = probability, for probability in (0, 1).
double normal_quantile(double probability);

// The regularized lower incomplete gamma function P(a, x) = gamma(a, x) / Gamma(a), a > 0, x >= 0.
double regularized_gamma_p(double a, double x);

// The regularized upper incomplete gamma function Q(a, x) = 1 - P(a, x), accurate when tiny.
double regularized_gamma_q(double a, double x);

// P(X <= x) for X chi-square distributed with `degrees_of_freedom` (> 0).
double chi_square_cdf(double x, double degrees_of_freedom);

// P(X > x) for X chi-square distributed: the p-value of a chi-square statistic x.
double chi_square_survival(double x, double degrees_of_freedom);

// The regularized incomplete beta function I_x(a, b), a > 0, b > 0, x in [0, 1].
double regularized_beta(double a, double b, double x);

// P(T <= t) for T Student-t distributed with `degrees_of_freedom` (> 0; infinity gives the normal).
double student_t_cdf(double t, double degrees_of_freedom);

// P(T > t) for T Student-t distributed, accurate when tiny.
double student_t_survival(double t, double degrees_of_freedom);

// P(|T| >= |t|): the two-sided p-value of a t statistic.
double student_t_two_sided_p_value(double t, double degrees_of_freedom);

// P(X >= k) for X ~ Binomial(trials, probability): the chance of k or more successes.
double binomial_survival(std::int64_t k, std::int64_t trials, double probability);

// The smallest count c with P(X > c) <= alpha for X ~ Binomial(trials, probability): a rule that
// fails when more than c of `trials` independent events of rate `probability` occur fails
// falsely with probability at most alpha.
std::int64_t binomial_critical_count(std::int64_t trials, double probability, double alpha);

// The per-test level that keeps the chance of any false rejection among `test_count` independent
// tests at `alpha`: 1 - (1 - alpha)^(1/m) (Šidák, J. Amer. Statist. Assoc. 62, 1967). Also valid
// (conservative) for two-sided tests of positively dependent normal statistics, by Šidák's inequality.
double sidak_alpha(double alpha, std::size_t test_count);

// The probability that a two-sided level-alpha z-test rejects when the true difference is
// `shift_in_standard_errors` standard errors: Phi(d - z) + Phi(-d - z), z = Phi^-1(1 - alpha / 2).
// Use it to choose a block size or a sample count before writing a test.
double normal_test_power(double shift_in_standard_errors, double alpha);

// --- t-tests ----------------------------------------------------------------------------------------

// A mean estimated from samples: its value, its variance (the squared standard error, i.e. sample
// variance / n) and the degrees of freedom of that variance estimate (n - 1 for n samples).
struct MeanEstimate {
    double mean = 0.0;
    double variance_of_mean = 0.0;
    double degrees_of_freedom = 0.0;
};

// The mean, variance of the mean and degrees of freedom of at least two values.
MeanEstimate estimate_mean(std::span<const double> values);

// Two exact answers are "equal" for the zero-variance rule below when they differ by at most this
// relative amount: images are stored in float, so the same number computed along two paths may
// differ in its last bits (a few units of 1.2e-7).
inline constexpr double zero_variance_relative_tolerance = 1e-6;

// The outcome of one hypothesis test.
struct TestResult {
    double statistic = 0.0;           // t
    double degrees_of_freedom = 0.0;
    double p_value = 1.0;             // two-sided
    bool passed = true;               // p_value > alpha
    std::string message;              // one line: what was compared and the verdict
};

// Tests the null hypothesis "the true mean is known_value" with Student's t-test, two-sided.
// When the variance is zero the test passes exactly when the means are equal (see above).
// one_sample_t_test({mean, variance_of_mean, dof}, known, alpha) picks the first form.
TestResult one_sample_t_test(const MeanEstimate& estimate, double known_value, double alpha);
TestResult one_sample_t_test(std::span<const double> values, double known_value, double alpha);

// Tests "both true means are equal" with Welch's unequal-variance t-test, two-sided; degrees of
// freedom by the Welch–Satterthwaite formula (Welch, Biometrika 34, 1947; Satterthwaite,
// Biometrics Bulletin 2, 1946). The second form takes sample counts (dof = n - 1).
TestResult welch_t_test(const MeanEstimate& first, const MeanEstimate& second, double alpha);
TestResult welch_t_test(double mean1, double variance_of_mean1, double n1, double mean2,
                        double variance_of_mean2, double n2, double alpha);

// The two-sided p-value of Welch's test alone, with the same zero-variance rule (1 when equal, 0
// when not) and 0 for invalid input; no message is built. For the thousands of tests of an image.
double welch_p_value(const MeanEstimate& first, const MeanEstimate& second);

// A number in short scientific form for messages ("1.23e-07").
std::string format_number(double value);

}  // namespace freezeray::stats
