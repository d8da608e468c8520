// Statistical comparison of renders: blockwise Welch and one-sample t-tests with a Šidák
// correction, and the per-pixel rule with its binomial allowance.
#include "image_tests.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace freezeray::stats {

namespace {

constexpr int channel_count = 3;
constexpr const char* channel_names[channel_count] = {"R", "G", "B"};

// One side of a comparison: a render (mean, variance of the mean, n - 1 degrees of freedom per
// pixel) or an exact image (no variance).
struct Side {
    const Image& mean;
    const Image* variance;  // nullptr: the values are exact
    double degrees_of_freedom;
};

Side render_side(const Image& mean, const Image& variance, std::uint64_t samples) {
    if (samples < 2)
        throw std::invalid_argument("image test: a render needs at least 2 samples per pixel to estimate its variance");
    return {mean, &variance, static_cast<double>(samples - 1)};
}

Side exact_side(const Image& known) { return {known, nullptr, 0.0}; }

void check_sizes(const Side& first, const Side& second) {
    const int width = first.mean.width();
    const int height = first.mean.height();
    if (width <= 0 || height <= 0) throw std::invalid_argument("image test: the image is empty");
    const auto same_size = [&](const Image& image) { return image.width() == width && image.height() == height; };
    if (!same_size(second.mean))
        throw std::invalid_argument("image test: the images differ in size (" + std::to_string(width) + "x" +
                                    std::to_string(height) + " vs " + std::to_string(second.mean.width()) + "x" +
                                    std::to_string(second.mean.height()) + ")");
    for (const Side* side : {&first, &second})
        if (side->variance && !same_size(*side->variance))
            throw std::invalid_argument("image test: a variance image is empty or not the size of its mean image");
}

// The mean of one channel over the pixels [x0, x1) x [y0, y1), with its variance and degrees of
// freedom. Pixels are independent, so the variance of the block mean is sum v_i / count^2; the
// degrees of freedom of that sum of variance estimates follow Satterthwaite (1946):
// (sum v_i)^2 / sum (v_i^2 / d), with d = n - 1 for every pixel.
MeanEstimate block_estimate(const Side& side, int x0, int y0, int x1, int y1, int channel) {
    double sum = 0.0;
    double variance_sum = 0.0;
    double variance_squares = 0.0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            sum += side.mean.at(x, y)[channel];
            if (side.variance) {
                const double v = side.variance->at(x, y)[channel];
                variance_sum += v;
                variance_squares += v * v;
            }
        }
    }
    const double count = static_cast<double>(x1 - x0) * (y1 - y0);
    MeanEstimate estimate;
    estimate.mean = sum / count;
    estimate.variance_of_mean = variance_sum / (count * count);
    estimate.degrees_of_freedom =
        variance_squares > 0.0 ? variance_sum * variance_sum * side.degrees_of_freedom / variance_squares : 0.0;
    return estimate;
}

// Tests every block and channel at per_test_alpha and fills the result's counts, p-value map and
// worst test. Returns the number of blocks in which any channel failed.
std::size_t test_blocks(const Side& first, const Side& second, int block_size, double per_test_alpha,
                        ImageTestResult& result) {
    if (block_size < 1) throw std::invalid_argument("image test: block_size must be at least 1");
    const int width = first.mean.width();
    const int height = first.mean.height();
    result.p_value_map = Image(width, height);
    result.worst.p_value = 2.0;
    std::size_t failed_blocks = 0;
    MeanEstimate worst_first, worst_second;
    for (int y0 = 0; y0 < height; y0 += block_size) {
        for (int x0 = 0; x0 < width; x0 += block_size) {
            const int x1 = std::min(x0 + block_size, width);
            const int y1 = std::min(y0 + block_size, height);
            Spectrum p_values(1.0f);
            bool block_failed = false;
            for (int channel = 0; channel < channel_count; ++channel) {
                const MeanEstimate a = block_estimate(first, x0, y0, x1, y1, channel);
                const MeanEstimate b = block_estimate(second, x0, y0, x1, y1, channel);
                const double p = welch_p_value(a, b);
                p_values[channel] = static_cast<float>(p);
                ++result.test_count;
                if (p <= per_test_alpha) {
                    ++result.failed_count;
                    block_failed = true;
                }
                if (p < result.worst.p_value) {
                    result.worst.p_value = p;
                    result.worst_x = x0;
                    result.worst_y = y0;
                    result.worst_channel = channel;
                    worst_first = a;
                    worst_second = b;
                }
            }
            if (block_failed) ++failed_blocks;
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) result.p_value_map.at(x, y) = p_values;
        }
    }
    // Only the worst test gets its full description (building thousands of messages is slow).
    result.worst = second.variance ? welch_t_test(worst_first, worst_second, per_test_alpha)
                                   : one_sample_t_test(worst_first, worst_second.mean, per_test_alpha);
    return failed_blocks;
}

std::string describe_worst(const ImageTestResult& result, const std::string& where) {
    return "worst: " + where + " at (" + std::to_string(result.worst_x) + ", " + std::to_string(result.worst_y) +
           "), channel " + channel_names[result.worst_channel] + ": " + result.worst.message;
}

ImageTestResult block_test(const std::string& name, const Side& first, const Side& second, int block_size,
                           double alpha) {
    check_sizes(first, second);
    ImageTestResult result;
    result.alpha = alpha;
    const std::size_t blocks = static_cast<std::size_t>((first.mean.width() + block_size - 1) / std::max(block_size, 1)) *
                               static_cast<std::size_t>((first.mean.height() + block_size - 1) / std::max(block_size, 1));
    result.per_test_alpha = sidak_alpha(alpha, blocks * channel_count);
    test_blocks(first, second, block_size, result.per_test_alpha, result);
    result.passed = result.failed_count == 0;
    const std::string size = std::to_string(block_size) + "x" + std::to_string(block_size);
    result.message = name + " (" + size + " blocks, per channel): " + (result.passed ? "passed" : "FAILED") + ", " +
                     std::to_string(result.failed_count) + " of " + std::to_string(result.test_count) +
                     " tests have p <= " + format_number(result.per_test_alpha) + " (alpha " + format_number(alpha) +
                     ", Sidak-corrected over " + std::to_string(result.test_count) + " tests)\n" +
                     describe_worst(result, "block");
    return result;
}

ImageTestResult pixel_rule(const Side& first, const Side& second, double pixel_alpha, double rule_alpha) {
    check_sizes(first, second);
    ImageTestResult result;
    result.alpha = rule_alpha;
    result.per_test_alpha = sidak_alpha(pixel_alpha, channel_count);  // a pixel fails with probability <= pixel_alpha
    const std::size_t failed_pixels = test_blocks(first, second, 1, result.per_test_alpha, result);
    const auto pixels = static_cast<std::int64_t>(first.mean.pixel_count());
    result.test_count = static_cast<std::size_t>(pixels);
    result.failed_count = failed_pixels;
    result.allowed_failures = binomial_critical_count(pixels, pixel_alpha, rule_alpha);
    result.rule_false_failure_rate = binomial_survival(result.allowed_failures + 1, pixels, pixel_alpha);
    result.passed = static_cast<std::int64_t>(failed_pixels) <= result.allowed_failures;
    const double must_pass = 100.0 * (1.0 - static_cast<double>(result.allowed_failures) / static_cast<double>(pixels));
    result.message = "per-pixel rule: " + std::string(result.passed ? "passed" : "FAILED") + ", " +
                     std::to_string(failed_pixels) + " of " + std::to_string(pixels) + " pixels fail at level " +
                     format_number(pixel_alpha) + ", at most " + std::to_string(result.allowed_failures) +
                     " may (at least " + format_number(must_pass) + " % must pass; the rule fails a correct render " +
                     "with probability " + format_number(result.rule_false_failure_rate) + " <= " +
                     format_number(rule_alpha) + ")\n" + describe_worst(result, "pixel");
    return result;
}

}  // namespace

ImageTestResult blockwise_welch_test(const Image& a_mean, const Image& a_variance, std::uint64_t a_samples,
                                     const Image& b_mean, const Image& b_variance, std::uint64_t b_samples,
                                     int block_size, double alpha) {
    return block_test("blockwise Welch test", render_side(a_mean, a_variance, a_samples),
                      render_side(b_mean, b_variance, b_samples), block_size, alpha);
}

ImageTestResult one_sample_image_test(const Image& mean, const Image& variance, std::uint64_t samples,
                                      const Image& known, int block_size, double alpha) {
    return block_test("one-sample image test", render_side(mean, variance, samples), exact_side(known), block_size,
                      alpha);
}

ImageTestResult one_sample_image_test(const Image& mean, const Image& variance, std::uint64_t samples,
                                      const Spectrum& known, int block_size, double alpha) {
    return one_sample_image_test(mean, variance, samples, Image(mean.width(), mean.height(), known), block_size, alpha);
}

ImageTestResult per_pixel_rule_test(const Image& a_mean, const Image& a_variance, std::uint64_t a_samples,
                                    const Image& b_mean, const Image& b_variance, std::uint64_t b_samples,
                                    double pixel_alpha, double rule_alpha) {
    return pixel_rule(render_side(a_mean, a_variance, a_samples), render_side(b_mean, b_variance, b_samples),
                      pixel_alpha, rule_alpha);
}

ImageTestResult per_pixel_rule_test(const Image& mean, const Image& variance, std::uint64_t samples,
                                    const Image& known, double pixel_alpha, double rule_alpha) {
    return pixel_rule(render_side(mean, variance, samples), exact_side(known), pixel_alpha, rule_alpha);
}

std::vector<double> channel_values(const Image& image, int channel) {
    std::vector<double> values;
    values.reserve(image.pixel_count());
    for (const Spectrum& p : image.pixels()) values.push_back(p[channel]);
    return values;
}

}  // namespace freezeray::stats
