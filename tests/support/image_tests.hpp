// Statistical comparison of renders. A render is what the film produces: the per-pixel mean, the
// per-pixel variance of that mean (sample variance / n) and the sample count n per pixel.
// Two renders made with independent seeds are compared block by block with Welch's t-test, a
// render is compared with an exact answer by the one-sample t-test, and the per-pixel rule asks
// that no more pixels fail than chance allows. See tests/STATISTICS.md for choosing the level and
// the block size.
//
// Tests are per colour channel, never on luminance: the film stores each channel's variance but
// not the covariance between channels, and luminance's variance needs both. The channel tests of a
// block are dependent (positively, in practice); the Šidák correction over blocks x channels stays
// valid for them by Šidák's inequality (it is then slightly conservative).
#pragma once

#include "statistics.hpp"

#include "freezeray/image.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace freezeray::stats {

struct ImageTestResult {
    bool passed = true;
    std::string message;  // the verdict, the levels and the worst block or pixel, a few lines

    double alpha = 0.0;           // the level asked for: the chance that a correct render fails
    double per_test_alpha = 0.0;  // the level of each block-channel (or pixel) test
    std::size_t test_count = 0;   // block-channel tests, or pixels for the per-pixel rule
    std::size_t failed_count = 0;  // tests (or pixels) with p <= per_test_alpha

    // The per-pixel rule only: how many pixels may fail, and the exact false-failure rate that
    // allowance gives (at most alpha; smaller because counts are whole numbers).
    std::int64_t allowed_failures = 0;
    double rule_false_failure_rate = 0.0;

    // The test with the smallest p-value: its block's top-left pixel (or the pixel), channel
    // (0 = R, 1 = G, 2 = B) and the t-test itself.
    int worst_x = 0;
    int worst_y = 0;
    int worst_channel = 0;
    TestResult worst;

    // Every pixel holds the p-value of its block's test (or of its own), per channel.
    Image p_value_map;
};

// Compares two renders made with independent seeds: the mean of every block_size x block_size block
// (smaller at the right and bottom edges), per channel, with Welch's t-test. Passes when no test has
// p <= sidak_alpha(alpha, blocks x 3). Throws std::invalid_argument on mismatched sizes, an empty
// variance image or fewer than 2 samples per pixel.
ImageTestResult blockwise_welch_test(const Image& a_mean, const Image& a_variance, std::uint64_t a_samples,
                                     const Image& b_mean, const Image& b_variance, std::uint64_t b_samples,
                                     int block_size, double alpha);

// Compares a render with the exact image (for the white furnace: Le / (1 - albedo) everywhere):
// the same block test with the one-sample t-test against the known block means.
ImageTestResult one_sample_image_test(const Image& mean, const Image& variance, std::uint64_t samples,
                                      const Image& known, int block_size, double alpha);
ImageTestResult one_sample_image_test(const Image& mean, const Image& variance, std::uint64_t samples,
                                      const Spectrum& known, int block_size, double alpha);

// The rule "no more pixels fail a per-pixel test at level pixel_alpha than chance allows": each pixel
// is tested (Welch, its 3 channels Šidák-corrected to pixel_alpha); the rule allows the binomial
// critical count of failures, binomial_critical_count(pixels, pixel_alpha, rule_alpha), so that a
// correct render fails it with probability at most rule_alpha. The message states the fraction of
// pixels that must pass ("at least 99.75 % of pixels").
ImageTestResult per_pixel_rule_test(const Image& a_mean, const Image& a_variance, std::uint64_t a_samples,
                                    const Image& b_mean, const Image& b_variance, std::uint64_t b_samples,
                                    double pixel_alpha, double rule_alpha);
ImageTestResult per_pixel_rule_test(const Image& mean, const Image& variance, std::uint64_t samples,
                                    const Image& known, double pixel_alpha, double rule_alpha);

// One channel (0 red, 1 green, 2 blue) of every pixel, in row order: the pixels as independent
// estimates of one value, for a t-test of a scene whose exact answer is the same everywhere.
std::vector<double> channel_values(const Image& image, int channel);

}  // namespace freezeray::stats
