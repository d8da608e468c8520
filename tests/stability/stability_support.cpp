// What the stability tests share (see the header).
#include "stability_support.hpp"

#include "evidence.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace freezeray::stability {

namespace {

constexpr const char* channel_names[3] = {"R", "G", "B"};

// A deterministic estimate's float rounding: relative deviations up to this are not biases.
constexpr double rounding_tolerance = 1e-5;

// The mean of one channel over some pixels, with the variance of that mean and its Satterthwaite
// degrees of freedom (as tests/support/image_tests.cpp does for blocks). Pixels within rounding of
// `known` count as exactly `known` (see energy_test).
stats::MeanEstimate group_estimate(const RenderResult& result, const std::vector<std::size_t>& pixels, int channel,
                                   double known) {
    const double dof = static_cast<double>(result.samples_per_pixel - 1);
    double sum = 0.0, variance_sum = 0.0, variance_squares = 0.0;
    for (const std::size_t i : pixels) {
        double mean = result.image[i][channel];
        double variance = result.variance[i][channel];
        const double scale = std::max(std::abs(known), 1e-3);
        if (std::abs(mean - known) <= rounding_tolerance * scale && variance <= std::pow(rounding_tolerance * scale, 2)) {
            mean = known;
            variance = 0.0;
        }
        sum += mean;
        variance_sum += variance;
        variance_squares += variance * variance;
    }
    const double count = static_cast<double>(pixels.size());
    stats::MeanEstimate estimate;
    estimate.mean = sum / count;
    estimate.variance_of_mean = variance_sum / (count * count);
    estimate.degrees_of_freedom = variance_squares > 0.0 ? variance_sum * variance_sum * dof / variance_squares : 0.0;
    return estimate;
}

// The pixels of every block_size x block_size block (smaller at the right and bottom edges).
std::vector<PixelGroup> blocks(int width, int height, int block_size) {
    std::vector<PixelGroup> result;
    for (int y0 = 0; y0 < height; y0 += block_size) {
        for (int x0 = 0; x0 < width; x0 += block_size) {
            PixelGroup block;
            block.name = "block at (" + std::to_string(x0) + ", " + std::to_string(y0) + ")";
            for (int y = y0; y < std::min(y0 + block_size, height); ++y)
                for (int x = x0; x < std::min(x0 + block_size, width); ++x)
                    block.pixels.push_back(static_cast<std::size_t>(y) * width + x);
            result.push_back(std::move(block));
        }
    }
    return result;
}

}  // namespace

std::string hard_scene(const std::string& relative) { return testing::scene_path("hard/" + relative); }

const std::vector<std::string>& all_integrators() {
    static const std::vector<std::string> names = {"pt-naive", "pt-is", "pt-nee", "pt-mis"};
    return names;
}

Scene load(const std::string& relative, int size) {
    SceneLoadOptions options;
    options.width = size;
    options.height = size;
    return load_scene(hard_scene(relative), testing::full_registry(), options);
}

RenderResult render(const HardRender& request) {
    testing::TestRender test_request;
    test_request.scene = hard_scene(request.scene);
    test_request.integrator = request.integrator;
    test_request.samples_per_pixel = request.samples_per_pixel;
    test_request.seed = request.seed;
    test_request.threads = 1;
    test_request.width = request.size;
    test_request.height = request.size;
    test_request.max_depth = request.max_depth;
    return testing::render(test_request);
}

void check_valid(const RenderResult& result, const std::string& what) {
    INFO(what);
    CHECK(result.invalid_samples == 0u);
    std::size_t bad_means = 0, bad_variances = 0;
    for (const Spectrum& p : result.image.pixels()) bad_means += is_valid_radiance(p) ? 0 : 1;
    for (const Spectrum& v : result.variance.pixels()) bad_variances += is_valid_radiance(v) ? 0 : 1;
    CHECK(bad_means == 0u);
    CHECK(bad_variances == 0u);
}

std::vector<int> pixel_coverage(const Scene& scene) {
    const Camera& camera = *scene.camera;
    const float offsets[5] = {0.0f, 0.25f, 0.5f, 0.75f, 0.9999f};
    std::vector<int> coverage(static_cast<std::size_t>(camera.width()) * camera.height());
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            int seen = 0;
            bool first = true;
            for (const float dy : offsets) {
                for (const float dx : offsets) {
                    const std::optional<Hit> hit = scene.intersect(camera.generate_ray(Vec2(x + dx, y + dy)));
                    const int mesh = hit ? static_cast<int>(hit->mesh) : Nothing;
                    if (first) seen = mesh;
                    else if (mesh != seen) seen = Mixed;
                    first = false;
                }
            }
            coverage[static_cast<std::size_t>(y) * camera.width() + x] = seen;
        }
    }
    return coverage;
}

std::vector<std::size_t> pixels_where(const std::vector<int>& coverage, int value) {
    std::vector<std::size_t> pixels;
    for (std::size_t i = 0; i < coverage.size(); ++i)
        if (coverage[i] == value) pixels.push_back(i);
    return pixels;
}

EnergyTestResult energy_test(const RenderResult& result, double known, Expectation expectation, int block_size,
                             const std::vector<PixelGroup>& groups, double alpha) {
    if (result.samples_per_pixel < 2) return {false, "energy test: a render needs at least 2 samples per pixel"};
    std::vector<PixelGroup> tested;
    if (block_size > 0) tested = blocks(result.image.width(), result.image.height(), block_size);
    for (const PixelGroup& g : groups)
        if (!g.pixels.empty()) tested.push_back(g);
    const double per_test_alpha = stats::sidak_alpha(alpha, tested.size() * 3);

    EnergyTestResult outcome;
    std::size_t failures = 0;
    double worst_p = 2.0;
    std::string worst;
    for (const PixelGroup& group : tested) {
        for (int c = 0; c < 3; ++c) {
            const stats::MeanEstimate estimate = group_estimate(result, group.pixels, c, known);
            // Two-sided for Equal; for AtMost only an excess counts, at one-sided level per_test_alpha.
            const stats::TestResult t = stats::one_sample_t_test(
                estimate, known, expectation == Expectation::Equal ? per_test_alpha : 2.0 * per_test_alpha);
            const bool counts = expectation == Expectation::Equal || estimate.mean > known;
            const double p = counts ? (expectation == Expectation::Equal ? t.p_value : 0.5 * t.p_value) : 1.0;
            const bool failed = counts && !t.passed;
            failures += failed ? 1 : 0;
            if (p < worst_p) {
                worst_p = p;
                std::ostringstream text;
                text << group.name << " (" << group.pixels.size() << " pixels), channel " << channel_names[c]
                     << ": mean " << estimate.mean << ", standard error " << std::sqrt(estimate.variance_of_mean)
                     << ", " << t.message;
                worst = text.str();
            }
        }
    }
    outcome.passed = failures == 0;
    std::ostringstream message;
    message << "energy test (" << (block_size > 0 ? "every " + std::to_string(block_size) + "x" + std::to_string(block_size) + " block and " : std::string())
            << groups.size() << " pixel groups, per channel, " << (expectation == Expectation::Equal ? "equal to " : "at most ")
            << known << "): " << (outcome.passed ? "passed" : "FAILED") << ", " << failures << " of "
            << tested.size() * 3 << " tests have p <= " << stats::format_number(per_test_alpha) << " (alpha "
            << stats::format_number(alpha) << ", Sidak-corrected)\nworst: " << worst;
    outcome.message = message.str();
    return outcome;
}

EnergyTestResult agreement_test(const RenderResult& a, const RenderResult& b, double tolerance, int block_size,
                                double alpha) {
    if (a.image.width() != b.image.width() || a.image.height() != b.image.height())
        return {false, "agreement test: the images differ in size"};
    if (a.samples_per_pixel < 2 || b.samples_per_pixel < 2)
        return {false, "agreement test: a render needs at least 2 samples per pixel"};
    const std::vector<PixelGroup> tested = blocks(a.image.width(), a.image.height(), block_size);
    const double per_test_alpha = stats::sidak_alpha(alpha, tested.size() * 3);
    std::size_t failures = 0;
    double worst_p = 2.0;
    std::string worst;
    for (const PixelGroup& block : tested) {
        for (int c = 0; c < 3; ++c) {
            // NaN as `known` keeps every pixel as it is (no rounding snap: both sides are renders).
            const stats::MeanEstimate ea = group_estimate(a, block.pixels, c, std::nan(""));
            stats::MeanEstimate eb = group_estimate(b, block.pixels, c, std::nan(""));
            const double margin = tolerance * std::max(std::abs(ea.mean), std::abs(eb.mean));
            eb.mean += std::clamp(ea.mean - eb.mean, -margin, margin);
            const stats::TestResult t = stats::welch_t_test(ea, eb, per_test_alpha);
            failures += t.passed ? 0 : 1;
            if (t.p_value < worst_p) {
                worst_p = t.p_value;
                worst = block.name + ", channel " + channel_names[c] + ": " + t.message;
            }
        }
    }
    EnergyTestResult outcome;
    outcome.passed = failures == 0;
    std::ostringstream message;
    message << "agreement test (" << block_size << "x" << block_size << " blocks, per channel, tolerance "
            << tolerance * 100.0 << " %): " << (outcome.passed ? "passed" : "FAILED") << ", " << failures << " of "
            << tested.size() * 3 << " tests have p <= " << stats::format_number(per_test_alpha) << " (alpha "
            << stats::format_number(alpha) << ", Sidak-corrected)\nworst: " << worst;
    outcome.message = message.str();
    return outcome;
}

std::string write_evidence(const std::string& test_name, const std::string& report,
                           const std::vector<std::pair<std::string, const RenderResult*>>& renders) {
    std::vector<stats::EvidenceImage> images;
    for (const auto& [name, result] : renders) {
        images.push_back({name, result->image});
        images.push_back({name + "-variance", result->variance});
    }
    return stats::write_evidence(test_name, images, report);
}

}  // namespace freezeray::stability
