// Tests of the statistical toolkit (tests/support) on synthetic data: the distributions against
// known values, each test's false-rejection rate over 2000 null cases, the chi-square harness on a
// right and on wrong warps, the power of the block test, and the evidence folder.
// Reference values were computed with mpmath (30 digits).
#include "chi_square.hpp"
#include "evidence.hpp"
#include "image_tests.hpp"
#include "statistics.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>

using namespace freezeray;
using namespace freezeray::stats;

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;
constexpr std::int64_t null_cases = 2000;
constexpr double null_alpha = 0.05;  // the level the null cases are run at: ~100 rejections expected

// Standard normal numbers, two from each pair of uniform ones (Box and Muller, "A Note on the
// Generation of Random Normal Deviates", Annals of Mathematical Statistics 29, 1958).
class NormalNumbers {
public:
    explicit NormalNumbers(PCG32 random) : random_(random) {}
    double next() {
        if (has_spare_) {
            has_spare_ = false;
            return spare_;
        }
        const double radius = std::sqrt(-2.0 * std::log(1.0 - random_.next_double()));
        const double angle = two_pi * random_.next_double();
        spare_ = radius * std::sin(angle);
        has_spare_ = true;
        return radius * std::cos(angle);
    }

private:
    PCG32 random_;
    double spare_ = 0.0;
    bool has_spare_ = false;
};

// A render as the film makes it: each pixel and channel averages `samples` normal samples of the
// given mean and standard deviation; the variance image is the sample variance / n.
struct SyntheticRender {
    Image mean, variance;
    std::uint64_t samples;
};

SyntheticRender synthetic_render(int width, int height, std::uint64_t samples, double mean, double deviation,
                                 std::uint64_t seed) {
    SyntheticRender render{Image(width, height), Image(width, height), samples};
    NormalNumbers normal(make_chain_stream(seed, 0));
    const double n = static_cast<double>(samples);
    for (std::size_t pixel = 0; pixel < render.mean.pixel_count(); ++pixel) {
        for (int channel = 0; channel < 3; ++channel) {
            double sum = 0.0, sum_of_squares = 0.0;
            for (std::uint64_t i = 0; i < samples; ++i) {
                const double value = mean + deviation * normal.next();
                sum += value;
                sum_of_squares += value * value;
            }
            const double sample_variance = (sum_of_squares - sum * sum / n) / (n - 1.0);
            render.mean[pixel][channel] = static_cast<float>(sum / n);
            render.variance[pixel][channel] = static_cast<float>(sample_variance / n);
        }
    }
    return render;
}

// Checks that `rejections` among `trials` null cases is a plausible count for a test whose true
// rejection rate is `rate`. The accepted range is the central binomial interval whose two tails
// each hold unit_test_alpha / 2, so this check itself fails falsely with probability <= 1e-6
// (derived from the budget in tests/STATISTICS.md, not tuned to the seeds). For 2000 cases at
// rate 0.05 it is [56, 151] around the expected 100.
void check_rejection_rate(std::int64_t rejections, std::int64_t trials, double rate) {
    const double tail = 0.5 * unit_test_alpha;
    const std::int64_t low = trials - binomial_critical_count(trials, 1.0 - rate, tail);
    const std::int64_t high = binomial_critical_count(trials, rate, tail);
    INFO(rejections << " rejections in " << trials << " null cases; expected " << rate * trials << ", accepted ["
                    << low << ", " << high << "]");
    CHECK(rejections >= low);
    CHECK(rejections <= high);
}

// Uniform directions on the sphere and cosine-weighted ones on the hemisphere, written inline so
// that these tests do not depend on the renderer's warps (Pharr et al., PBRT 3rd ed., 13.6).
std::optional<Vec3> sample_sphere(PCG32& random) {
    const double z = 1.0 - 2.0 * random.next_double();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = two_pi * random.next_double();
    return Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
}

std::optional<Vec3> sample_cosine_hemisphere(PCG32& random) {
    const double r = std::sqrt(random.next_double());
    const double phi = two_pi * random.next_double();
    return Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::sqrt(std::max(0.0, 1.0 - r * r))));
}

double sphere_pdf(const Vec3&) { return 1.0 / (4.0 * std::numbers::pi); }
double cosine_pdf(const Vec3& w) { return w.z > 0.0f ? w.z / std::numbers::pi : 0.0; }

}  // namespace

TEST_CASE("normal distribution matches known values", "[unit][statistics]") {
    CHECK(normal_cdf(-1.0) == Approx(0.158655253931457051).epsilon(1e-13));
    CHECK(normal_cdf(-8.0) == Approx(6.22096057427178412e-16).epsilon(1e-12));
    CHECK(normal_cdf(-20.0) == Approx(2.75362411860623370e-89).epsilon(1e-12));
    CHECK(normal_quantile(0.975) == Approx(1.95996398454005424).epsilon(1e-14));
    CHECK(normal_quantile(1e-10) == Approx(-6.36134090240405620).epsilon(1e-14));
    for (double p : {1e-300, 1e-12, 0.01, 0.3, 0.5, 0.8, 0.999999})
        CHECK(normal_cdf(normal_quantile(p)) == Approx(p).epsilon(1e-12));
}

TEST_CASE("chi-square distribution matches known values", "[unit][statistics]") {
    CHECK(chi_square_survival(3.841458820694124, 1) == Approx(0.05).epsilon(1e-12));
    CHECK(chi_square_survival(18.307038053275146, 10) == Approx(0.05).epsilon(1e-12));
    CHECK(chi_square_survival(100.0, 1) == Approx(1.52397060483210521e-23).epsilon(1e-10));
    CHECK(chi_square_survival(300.0, 200) == Approx(5.92454033548391583e-6).epsilon(1e-10));
    CHECK(chi_square_survival(1500.0, 1000) == Approx(1.04546403859796573e-22).epsilon(1e-9));
    CHECK(chi_square_cdf(150.0, 200) == Approx(3.35244149818699189e-3).epsilon(1e-10));
    CHECK(chi_square_survival(7.0, 2) == Approx(std::exp(-3.5)).epsilon(1e-13));  // exp(-x / 2) for 2 dof
    for (double x : {0.5, 3.0, 40.0})
        CHECK(regularized_gamma_p(2.5, x) + regularized_gamma_q(2.5, x) == Approx(1.0).epsilon(1e-14));
}

TEST_CASE("Student t distribution matches known values", "[unit][statistics]") {
    CHECK(student_t_survival(2.2281388519649385, 10) == Approx(0.025).epsilon(1e-10));
    CHECK(student_t_survival(6.0, 30) == Approx(6.97138438360237135e-7).epsilon(1e-10));
    CHECK(student_t_survival(40.0, 5) == Approx(9.20598108588647718e-8).epsilon(1e-10));
    CHECK(student_t_survival(6.0, 1e6) == Approx(9.86924906177217335e-10).epsilon(1e-9));
    CHECK(student_t_survival(3.0, 1) == Approx(0.5 - std::atan(3.0) / std::numbers::pi).epsilon(1e-13));  // Cauchy
    CHECK(student_t_cdf(-1.5, 2) == Approx(0.5 * (1.0 - 1.5 / std::sqrt(2.0 + 2.25))).epsilon(1e-13));
    CHECK(student_t_two_sided_p_value(2.5, std::numeric_limits<double>::infinity()) == Approx(2.0 * normal_cdf(-2.5)).epsilon(1e-14));
}

TEST_CASE("incomplete beta and binomial tail and Sidak level agree with known values", "[unit][statistics]") {
    CHECK(regularized_beta(2.5, 7.5, 0.3) == Approx(0.678943485866181631).epsilon(1e-12));
    CHECK(regularized_beta(200, 300, 0.5) == Approx(0.999996456519735607).epsilon(1e-12));
    CHECK(regularized_beta(3.0, 1.0, 0.4) == Approx(std::pow(0.4, 3.0)).epsilon(1e-13));
    CHECK(binomial_survival(8, 30, 0.1) == Approx(7.78361923792131236e-3).epsilon(1e-11));
    CHECK(binomial_survival(100, 65536, 0.001) == Approx(4.50644079155166594e-5).epsilon(1e-9));
    const std::int64_t c = binomial_critical_count(65536, 0.001, 1e-5);
    CHECK(binomial_survival(c + 1, 65536, 0.001) <= 1e-5);
    CHECK(binomial_survival(c, 65536, 0.001) > 1e-5);
    const double per_test = sidak_alpha(1e-5, 768);
    CHECK(1.0 - std::pow(1.0 - per_test, 768) == Approx(1e-5).epsilon(1e-9));
    CHECK(sidak_alpha(0.05, 1) == Approx(0.05).epsilon(1e-15));
}

TEST_CASE("t-tests reject true null hypotheses at their stated rate", "[unit][statistics]") {
    NormalNumbers normal(make_chain_stream(20240601, 0));
    std::int64_t one_sample_rejections = 0, welch_rejections = 0;
    for (std::int64_t trial = 0; trial < null_cases; ++trial) {
        std::vector<double> values(10), first(5), second(20);
        for (double& v : values) v = 3.0 + 2.0 * normal.next();
        if (!one_sample_t_test(values, 3.0, null_alpha).passed) ++one_sample_rejections;
        // Unequal sizes and variances: Welch's approximate dof is what is being tested.
        for (double& v : first) v = 1.0 + normal.next();
        for (double& v : second) v = 1.0 + 3.0 * normal.next();
        if (!welch_t_test(estimate_mean(first), estimate_mean(second), null_alpha).passed) ++welch_rejections;
    }
    check_rejection_rate(one_sample_rejections, null_cases, null_alpha);
    check_rejection_rate(welch_rejections, null_cases, null_alpha);
}

TEST_CASE("t-tests decide zero-variance cases by equality", "[unit][statistics]") {
    CHECK(welch_t_test(0.0, 0.0, 16, 0.0, 0.0, 16, 1e-5).passed);
    CHECK_FALSE(welch_t_test(0.0, 0.0, 16, 0.25, 0.0, 16, 1e-5).passed);
    CHECK(one_sample_t_test(MeanEstimate{2.0f / 3.0f, 0.0, 15}, 2.0 / 3.0, 1e-5).passed);  // equal up to float rounding
    CHECK_FALSE(one_sample_t_test(MeanEstimate{std::nan(""), 0.1, 15}, 1.0, 1e-5).passed);
    const TestResult shifted = one_sample_t_test(MeanEstimate{1.0, 0.01, 15}, 0.0, 1e-5);  // t = 10
    CHECK(shifted.statistic == Approx(10.0));
    CHECK_FALSE(shifted.passed);
}

TEST_CASE("chi-square harness rejects a correct warp at its stated rate", "[unit][statistics]") {
    ChiSquareOptions options;
    options.sample_count = 2000;
    options.resolution = 3;  // 18 cells of about 111 expected samples
    options.alpha = null_alpha;
    std::int64_t rejections = 0;
    for (std::int64_t trial = 0; trial < null_cases; ++trial) {
        options.seed = static_cast<std::uint64_t>(trial);
        if (!chi_square_test(Domain::sphere(), sample_sphere, sphere_pdf, options).passed) ++rejections;
    }
    check_rejection_rate(rejections, null_cases, null_alpha);
}

TEST_CASE("chi-square harness passes correct warps", "[unit][statistics]") {
    const ChiSquareResult sphere = chi_square_test(Domain::sphere(), sample_sphere, sphere_pdf);
    INFO(sphere.message);
    CHECK(sphere.passed);
    CHECK(sphere.degrees_of_freedom == 199);
    CHECK(sphere.pdf_integral == Approx(1.0).epsilon(1e-9));
    const ChiSquareResult cosine = chi_square_test(Domain::hemisphere(), sample_cosine_hemisphere, cosine_pdf);
    INFO(cosine.message);
    CHECK(cosine.passed);
    // The harness's quadrature also checks integrals such as "cos integrates to pi".
    CHECK(integrate_over_domain(Domain::hemisphere(), [](const Vec3& w) { return double(w.z); }) ==
          Approx(std::numbers::pi).epsilon(1e-6));
    // A sampler that sometimes returns nothing, with the pdf per attempt (integral 1/2).
    ChiSquareOptions options;
    options.expected_pdf_integral = 0.5;
    const ChiSquareResult half = chi_square_test(
        Domain::sphere(), [](PCG32& random) { return random.next_float() < 0.5f ? sample_sphere(random) : std::nullopt; },
        [](const Vec3& w) { return 0.5 * sphere_pdf(w); }, options);
    INFO(half.message);
    CHECK(half.passed);
}

TEST_CASE("chi-square harness catches wrong warps", "[unit][statistics]") {
    SECTION("a cosine-weighted sampler with the uniform pdf (a missing cosine)") {
        const ChiSquareResult result = chi_square_test(Domain::hemisphere(), sample_cosine_hemisphere,
                                                       [](const Vec3&) { return 1.0 / two_pi; });
        CHECK_FALSE(result.passed);
        CHECK(result.p_value < 1e-100);
    }
    SECTION("a sampler biased by 5 % in cos(theta)") {
        // Noncentrality 1e6 sum (p' - p)^2 / p = 2177 over the cos(theta) bands: the statistic is
        // about 2376 +- 95 against a critical value near 300, so it never passes.
        const auto biased = [](PCG32& random) {
            const double z = 1.0 - 2.0 * std::pow(random.next_double(), 1.05);
            const double r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = two_pi * random.next_double();
            return std::optional<Vec3>(Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
        };
        const ChiSquareResult result = chi_square_test(Domain::sphere(), biased, sphere_pdf);
        CHECK_FALSE(result.passed);
        CHECK(result.p_value < chi_square_test_alpha);
    }
    SECTION("samples where the pdf is zero") {
        const ChiSquareResult result = chi_square_test(Domain::sphere(), sample_sphere, cosine_pdf);
        CHECK_FALSE(result.passed);
        CHECK(result.samples_with_zero_pdf > 0);
        CHECK_THAT(result.message, Catch::Contains("pdf(sample) zero"));
    }
    SECTION("a sampler that fails, with a pdf that ignores its failures") {
        const ChiSquareResult result = chi_square_test(
            Domain::sphere(),
            [](PCG32& random) { return random.next_float() < 0.9f ? sample_sphere(random) : std::nullopt; },
            sphere_pdf);
        CHECK_FALSE(result.passed);
        CHECK_THAT(result.message, Catch::Contains("returned nothing"));
    }
    SECTION("a pdf twice too large") {
        const ChiSquareResult result =
            chi_square_test(Domain::sphere(), sample_sphere, [](const Vec3&) { return 1.0 / two_pi; });
        CHECK_FALSE(result.passed);
        CHECK(result.pdf_integral == Approx(2.0).epsilon(1e-9));
        CHECK_THAT(result.message, Catch::Contains("integrates to 2"));
    }
}

TEST_CASE("image tests reject equal renders at their stated rate", "[unit][statistics]") {
    // 2000 pairs of 12x12 renders of 8 samples per pixel: 9 blocks of 4x4, 27 block tests.
    std::int64_t welch_rejections = 0, one_sample_rejections = 0, rule_rejections = 0;
    double rule_rate = 0.0;
    const Image known(12, 12, Spectrum(0.5f));
    for (std::int64_t trial = 0; trial < null_cases; ++trial) {
        const auto seed = static_cast<std::uint64_t>(2 * trial);
        const SyntheticRender a = synthetic_render(12, 12, 8, 0.5, 0.4, seed);
        const SyntheticRender b = synthetic_render(12, 12, 8, 0.5, 0.8, seed + 1);
        if (!blockwise_welch_test(a.mean, a.variance, 8, b.mean, b.variance, 8, 4, null_alpha).passed)
            ++welch_rejections;
        if (!one_sample_image_test(a.mean, a.variance, 8, known, 4, null_alpha).passed) ++one_sample_rejections;
        const ImageTestResult rule = per_pixel_rule_test(a.mean, a.variance, 8, b.mean, b.variance, 8, 0.05, null_alpha);
        rule_rate = rule.rule_false_failure_rate;  // exact, below null_alpha since counts are whole
        if (!rule.passed) ++rule_rejections;
    }
    check_rejection_rate(welch_rejections, null_cases, null_alpha);
    check_rejection_rate(one_sample_rejections, null_cases, null_alpha);
    check_rejection_rate(rule_rejections, null_cases, rule_rate);
}

TEST_CASE("image tests handle zero-variance pixels", "[unit][statistics]") {
    SyntheticRender a = synthetic_render(32, 32, 16, 0.5, 0.3, 7);
    SyntheticRender b = synthetic_render(32, 32, 16, 0.5, 0.3, 8);
    for (int y = 0; y < 32; ++y)  // a black background on the left half of both renders
        for (int x = 0; x < 16; ++x) a.mean.at(x, y) = a.variance.at(x, y) = b.mean.at(x, y) = b.variance.at(x, y) = Spectrum(0.0f);
    const ImageTestResult same = blockwise_welch_test(a.mean, a.variance, 16, b.mean, b.variance, 16, 8, unit_test_alpha);
    INFO(same.message);
    CHECK(same.passed);
    CHECK(per_pixel_rule_test(a.mean, a.variance, 16, b.mean, b.variance, 16, 1e-3, unit_test_alpha).passed);
    b.mean.at(3, 3) = Spectrum(0.0f, 0.25f, 0.0f);  // the background differs, without noise
    const ImageTestResult different = blockwise_welch_test(a.mean, a.variance, 16, b.mean, b.variance, 16, 8, 1e-5);
    CHECK_FALSE(different.passed);
    CHECK(different.worst_channel == 1);
    CHECK(different.worst.p_value == 0.0);
    const Image exact(32, 32, Spectrum(0.75f));
    CHECK(one_sample_image_test(exact, Image(32, 32), 16, Spectrum(0.75f), 8, 1e-5).passed);
    CHECK_FALSE(one_sample_image_test(exact, Image(32, 32), 16, Spectrum(0.7f), 8, 1e-5).passed);
}

TEST_CASE("block test detects a 2% bias in a 64-spp render", "[unit][statistics]") {
    // 256x256, 64 samples per pixel with a coefficient of variation of 1 (pixel noise 12.5 %, a
    // typical 64-spp path-traced image); 64x64 blocks, 16 blocks x 3 channels, at the level of a
    // convergence test. Each block difference is 0.02 / sqrt(2 / (64 x 4096)) = 7.2 standard errors.
    const int size = 256, block = 64;
    const std::uint64_t spp = 64;
    const double bias = 0.02;
    const std::size_t tests = 3 * (size / block) * (size / block);
    const double per_test_alpha = sidak_alpha(convergence_test_alpha, tests);
    const double shift = bias / std::sqrt(2.0 / (double(spp) * block * block));
    const double miss_probability = std::pow(1.0 - normal_test_power(shift, per_test_alpha), double(tests));
    INFO("per-block power " << normal_test_power(shift, per_test_alpha) << ", miss probability " << miss_probability);
    // Per block 0.96 at convergence_test_alpha = 2.5e-6 (0.97 before chapter 10 halved it); what
    // matters is that all 48 blocks together miss the bias with probability below 1e-6.
    CHECK(normal_test_power(shift, per_test_alpha) > 0.95);
    CHECK(miss_probability < unit_test_alpha);  // so the assertion below fails falsely with p < 1e-6

    const SyntheticRender reference = synthetic_render(size, size, spp, 1.0, 1.0, 100);
    const SyntheticRender biased = synthetic_render(size, size, spp, 1.0 + bias, 1.0 + bias, 101);
    const ImageTestResult result = blockwise_welch_test(reference.mean, reference.variance, spp, biased.mean,
                                                        biased.variance, spp, block, convergence_test_alpha);
    INFO(result.message);
    CHECK_FALSE(result.passed);
}

TEST_CASE("evidence is written when a test fails", "[unit][statistics]") {
    CHECK(sanitize_test_name("chi2: GGX (alpha = 0.1) / sample") == "chi2_GGX_alpha_0_1_sample");
    CHECK(sanitize_test_name("..") == "unnamed-test");

    const ChiSquareResult wrong = chi_square_test(Domain::hemisphere(), sample_cosine_hemisphere,
                                                  [](const Vec3&) { return 1.0 / two_pi; });
    REQUIRE_FALSE(wrong.passed);
    const std::filesystem::path folder = write_evidence("statistics self-test: chi2 evidence", wrong);
    CHECK(folder.filename() == "statistics_self-test_chi2_evidence");
    for (const char* file : {"observed.pfm", "expected.pfm", "deviation.pfm", "report.txt"})
        CHECK(std::filesystem::exists(folder / file));
    std::ifstream report(folder / "report.txt");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    CHECK_THAT(text, Catch::Contains("FAILED") && Catch::Contains("observed, expected"));

    const SyntheticRender a = synthetic_render(16, 16, 8, 0.5, 0.1, 1);
    const ImageTestResult failed = one_sample_image_test(a.mean, a.variance, 8, Spectrum(0.6f), 8, 1e-5);
    REQUIRE_FALSE(failed.passed);
    const std::filesystem::path image_folder =
        write_evidence("statistics self-test: image evidence", failed, {{"mean", a.mean}, {"variance", a.variance}});
    for (const char* file : {"mean.pfm", "variance.pfm", "p_values.pfm", "report.txt"})
        CHECK(std::filesystem::exists(image_folder / file));
    std::filesystem::remove_all(folder);  // forced failures: nothing to keep
    std::filesystem::remove_all(image_folder);
}
