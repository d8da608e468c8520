// pt-naive converges to the right answer, at the right rate, reproducibly.
#include "freezeray/comparison.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/metrics.hpp"
#include "freezeray/progress.hpp"

#include "statistics.hpp"
#include "determinism.hpp"
#include "image_tests.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace freezeray;

TEST_CASE("pt-naive matches Le / (1 - albedo) in the furnace", "[convergence][ch01]") {
    // Le = 0.5, albedo = 0.5: the exact radiance is 1 in every direction. Truncation at 64
    // segments changes it by 0.5^64, far below the noise. Every pixel is an independent estimate
    // of the same value, so the pixels' mean is tested with a t-test (false-failure rate 1e-5).
    testing::TestRender request;
    request.scene = testing::scene_path("furnace/scene.json");
    request.samples_per_pixel = 64;
    request.seed = 17;
    const RenderResult result = testing::render(request);
    REQUIRE(result.invalid_samples == 0u);
    for (int c = 0; c < 3; ++c) {
        const stats::TestResult test =
            stats::one_sample_t_test(stats::channel_values(result.image, c), 1.0, stats::convergence_test_alpha);
        INFO("channel " << c << ": " << test.message);
        CHECK(test.passed);
    }
}

TEST_CASE("pt-naive's MSE against a reference falls like 1/N", "[convergence][ch01]") {
    // One render of the Cornell box at 32x32, with the film captured after every pass (1, 2, 4,
    // ..., 256 samples per pixel), against an independent 4096-spp reference. The expected MSE
    // is sigma^2 / N + (the reference's own variance), so the reference's estimated variance is
    // subtracted before fitting log(MSE) = a + slope log(N) by least squares.
    testing::TestRender reference_request;
    reference_request.scene = testing::scene_path("cornell-box/scene.json");
    reference_request.width = reference_request.height = 32;
    reference_request.samples_per_pixel = 4096;
    reference_request.seed = 1000;
    const RenderResult reference = testing::render(reference_request);
    double reference_variance = 0.0;
    for (const Spectrum& v : reference.variance.pixels()) reference_variance += (v.r + v.g + v.b) / 3.0;
    reference_variance /= static_cast<double>(reference.variance.pixel_count());

    SceneLoadOptions options;
    options.width = options.height = 32;
    const Scene scene = load_scene(reference_request.scene, testing::full_registry(), options);
    RenderSettings settings;
    settings.samples_per_pixel = 256;
    settings.seed = 2000;
    std::vector<double> log_n, log_mse;
    settings.on_pass = [&](const Film& film, std::uint64_t spp, double) {
        const double error = mse(film.mean(), reference.image) - reference_variance;
        if (spp >= 2 && error > 0.0) {
            log_n.push_back(std::log(static_cast<double>(spp)));
            log_mse.push_back(std::log(error));
        }
    };
    Progress quiet(true);
    testing::full_registry().integrators.make("pt-naive", "test", settings, Parameters::none())->render(scene, settings, quiet);
    REQUIRE(log_n.size() >= 6u);

    const double slope = fit_line(log_n, log_mse).slope;
    INFO("fitted slope of log MSE against log N: " << slope);
    CHECK(slope == Approx(-1.0).margin(0.15));
}

TEST_CASE("an image is bit-identical with 1 and 2 threads", "[convergence][determinism]") {
    testing::TestRender request;
    request.scene = testing::scene_path("cornell-box/scene.json");
    request.width = request.height = 40;  // not a multiple of the tile size
    request.samples_per_pixel = 6;        // passes of 1, 1, 2, 2
    request.seed = 99;
    testing::check_thread_count_independent(request);
}

TEST_CASE("pt-naive's default maximum depth loses under 1% of the Cornell box's light", "[convergence][ch01]") {
    // The same seed at the default depth and at depth 100 follows the same paths for the first
    // segments, so the difference of the two means is what the deeper segments add: the
    // truncation bias of the default (measured 0.10% in the book; the test allows 1%).
    testing::TestRender request;
    request.scene = testing::scene_path("cornell-box/scene.json");
    request.width = request.height = 32;
    request.samples_per_pixel = 256;
    request.seed = 7;
    const RenderResult truncated = testing::render(request);
    request.max_depth = 100;
    const RenderResult deep = testing::render(request);
    double truncated_mean = 0, deep_mean = 0;
    for (std::size_t i = 0; i < deep.image.pixel_count(); ++i) {
        truncated_mean += luminance(truncated.image[i]);
        deep_mean += luminance(deep.image[i]);
    }
    const double lost = (deep_mean - truncated_mean) / deep_mean;
    INFO("fraction of the light lost by truncation: " << lost);
    CHECK(lost >= 0.0);
    CHECK(lost < 0.01);
}
