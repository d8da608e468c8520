// Grading tests of chapter 01's exercises. Each test case is named after its exercise and
// checks the student's code against an exact or statistical answer.
#include "freezeray/ch01/lambertian.hpp"
#include "freezeray/ch01/warps.hpp"

#include "bias_detectors.hpp"
#include "chi_square.hpp"
#include "evidence.hpp"
#include "image_tests.hpp"
#include "reference_blocks.hpp"
#include "statistics.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace freezeray;
using namespace freezeray::ch01;

TEST_CASE("ch01/uniform-hemisphere", "[exercise]") {
    // Every direction is a unit vector on the upper hemisphere, and their distribution over the
    // whole sphere matches the density 1/(2 pi) on z >= 0 (chi-square, false-failure rate 1e-6).
    // When it does not, the samples are tested against the densities of two classic mistakes,
    // and the one they fit is named (bias_detectors.hpp).
    PCG32 random(11, 1);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 w = sample_uniform_hemisphere(Vec2(random.next_float(), random.next_float()));
        REQUIRE(glm::length(w) == Approx(1.0f).margin(1e-5));
        REQUIRE(w.z >= 0.0f);
    }
    stats::ChiSquareOptions options;
    options.alpha = stats::exercise_test_alpha;
    const double pi = 3.14159265358979323846;
    const stats::SampleFunction sample = [](PCG32& r) -> std::optional<Vec3> {
        return sample_uniform_hemisphere(Vec2(r.next_float(), r.next_float()));
    };
    const auto result = stats::chi_square_test(stats::Domain::sphere(), sample,
                                               [&](const Vec3& w) { return w.z >= 0.0f ? 1.0 / (2.0 * pi) : 0.0; }, options);
    INFO(result.message);
    const auto direction = [](const Vec3& w) { return w; };
    const std::vector<testing::DensitySuspect> suspects{
        // theta = (pi / 2) u: uniform in theta, tested on theta itself (density 2 / pi on [0, pi/2];
        // per solid angle it would be 1 / (pi^2 sin theta), singular at the pole).
        {"theta uniform in [0, pi/2] instead of cos theta uniform in [0, 1] (the density is then "
         "1 / (pi^2 sin theta), not 1 / (2 pi))",
         stats::Domain::interval(0.0, pi / 2.0),
         [](const Vec3& w) { return Vec3(std::acos(std::clamp(w.z, -1.0f, 1.0f)), 0.0f, 0.0f); },
         [&](const Vec3&) { return 2.0 / pi; }},
        // cos theta = sqrt(u): the cosine-weighted density of chapter 02.
        {"cos theta = sqrt(u) (that is cosine-weighted, density cos theta / pi, chapter 02's)", stats::Domain::sphere(),
         direction, [&](const Vec3& w) { return w.z >= 0.0f ? double(w.z) / pi : 0.0; }},
    };
    const std::string hint = result.passed ? "" : testing::likely_density_mistake(sample, suspects, options);
    INFO(hint);
    // On failure, the chi-square table as images (observed, expected, deviation per cell).
    const std::string evidence = result.passed ? "" : "evidence: " + stats::write_evidence("ch01/uniform-hemisphere", result);
    INFO(evidence);
    CHECK(result.passed);
}

TEST_CASE("ch01/lambertian-brdf", "[exercise]") {
    const Spectrum albedo(0.8f, 0.5f, 0.2f);
    const LambertianBSDF bsdf(albedo);
    const Vec3 up = glm::normalize(Vec3(0.2f, -0.4f, 0.9f));
    const Vec3 up2 = glm::normalize(Vec3(-0.7f, 0.1f, 0.3f));
    const Vec3 down = glm::normalize(Vec3(0.1f, 0.3f, -0.5f));
    // f = albedo / pi for directions on the same side, on either side of the surface.
    const Spectrum expected = albedo / 3.14159265f;
    for (int c = 0; c < 3; ++c) {
        CHECK(bsdf.eval(up, up2)[c] == Approx(expected[c]));
        CHECK(bsdf.eval(-up, -up2)[c] == Approx(expected[c]));
        CHECK(bsdf.eval(up, down)[c] == 0.0f);   // a Lambertian surface does not transmit
        CHECK(bsdf.eval(down, up2)[c] == 0.0f);
    }
    // Energy: the integral of f cos over the hemisphere is the albedo (midpoint rule in
    // cos(theta), exact for a constant f).
    Spectrum integral(0.0f);
    constexpr int Steps = 200;
    for (int i = 0; i < Steps; ++i) {
        const float cos_theta = (i + 0.5f) / Steps;
        const Vec3 wi(std::sqrt(1 - cos_theta * cos_theta), 0.0f, cos_theta);
        integral += bsdf.eval(up, wi) * cos_theta * (2.0f * 3.14159265f / Steps);
    }
    for (int c = 0; c < 3; ++c) CHECK(integral[c] == Approx(albedo[c]).epsilon(1e-3));
}

TEST_CASE("ch01/path-throughput", "[exercise]") {
    // The furnace: the radiance is exactly Le / (1 - albedo) = 1 in every direction. The mean of
    // the pixels must match it within a t-test at false-failure rate 1e-6 (the pixels are
    // independent estimates of the same value).
    testing::TestRender request;
    request.scene = testing::scene_path("furnace/scene.json");
    request.samples_per_pixel = 16;
    request.width = 16;
    request.height = 16;
    request.seed = 5;
    request.accelerator = "bruteforce";  // chapter 01's own (the KD-tree would run chapter 06's exercises)
    const RenderResult result = testing::render(request);
    const stats::TestResult test = stats::one_sample_t_test(stats::channel_values(result.image, 1), 1.0, stats::exercise_test_alpha);

    // Paths of at most two segments (one bounce): exactly Le (1 + albedo) = 0.75. Short paths
    // make the classic mistakes' answers exact too, Le (1 + q) with q the mistaken weight's mean
    // (bias_detectors.hpp), without the heavy tails that long products of a wrong weight have;
    // their answers are at least 6 % apart, and this mean's standard error is about 0.5 %.
    request.max_depth = 2;
    const std::vector<double> short_paths = stats::channel_values(testing::render(request).image, 1);
    const stats::TestResult test_short = stats::one_sample_t_test(short_paths, 0.75, stats::exercise_test_alpha);
    const double mean = stats::estimate_mean(short_paths).mean;
    INFO(test.message);
    INFO(test_short.message);
    const std::string hint = test.passed && test_short.passed
                                 ? ""
                                 : testing::likely_mistake(mean, testing::furnace_suspects(0.5, 0.5, 2), 0.025);
    INFO(hint);
    CHECK(test.passed);
    CHECK(test_short.passed);
    CHECK(result.invalid_samples == 0u);

    // The same sphere seen from outside, white (albedo 1) under a constant sky of radiance 1:
    // every pixel is 1. The sphere is wound inward, so the camera sees its back faces, where
    // cos theta_i < 0 in the shading frame: a weight with cos instead of |cos| turns negative,
    // and the film counts negative samples as invalid (and adds them as zero).
    request.scene = testing::scene_path("furnace/scene-environment.json");
    request.max_depth = 0;
    const RenderResult outside = testing::render(request);
    const stats::TestResult test_outside = stats::one_sample_t_test(stats::channel_values(outside.image, 1), 1.0, stats::exercise_test_alpha);
    INFO(test_outside.message);
    const std::string sign_hint =
        outside.invalid_samples == 0
            ? ""
            : "likely mistake: cos theta_i without its absolute value (on a back face it is negative, and so is the "
              "weight: " + std::to_string(outside.invalid_samples) + " negative samples)";
    INFO(sign_hint);
    CHECK(test_outside.passed);
    CHECK(outside.invalid_samples == 0u);
}

TEST_CASE("ch01/naive-path-tracer", "[exercise]") {
    // The assignment (tests/grading/assignments.json): this chapter's exercises together render the
    // Cornell box with pt-naive as the solution does. 8 independent renders of 128 samples per pixel;
    // each block of pixels, and the whole image, against the solution's reference (make_references.py
    // --blocks, other seeds, 8 to 32 times the samples), false-failure rate exercise_test_alpha for
    // the whole comparison (reference_blocks.hpp).
    const testing::ReferenceComparison comparison =
        testing::compare_with_reference("ch01/naive-path-tracer", 8, 128, 1, stats::exercise_test_alpha);
    INFO(comparison.message);
    INFO(comparison.evidence);
    CHECK(comparison.passed);
}
