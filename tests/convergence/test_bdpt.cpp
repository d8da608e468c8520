// Chapter 04's bidirectional path tracing: deterministic images, its weighted strategy images
// adding up to the render, the furnaces' closed forms, and agreement with pt-mis on the course's
// scenes (Veach 1997, chapter 10). Statistical tests and their false-failure rates: see each
// test case and tests/STATISTICS.md (label convergence).
#include "freezeray/image.hpp"

#include "evidence.hpp"
#include "image_tests.hpp"
#include "independent_runs.hpp"
#include "statistics.hpp"
#include "determinism.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace freezeray;

namespace {

RenderResult render_bdpt(const std::string& scene, std::uint64_t seed, std::uint64_t spp, int size, int threads = 0,
                         bool strategy_images = false, int max_depth = 64, const std::string& integrator = "bdpt") {
    testing::TestRender request;
    request.scene = testing::scene_path(scene);
    request.integrator = integrator;
    request.width = request.height = size;
    request.samples_per_pixel = spp;
    request.seed = seed;
    request.threads = threads;
    request.max_depth = max_depth;
    request.strategy_images = strategy_images;
    return testing::render(request);
}

void require_bdpt_agrees(const std::string& integrator, const std::string& scene, std::uint64_t seed,
                         const std::vector<int>& blocks) {
    testing::SplattingAgreement request;
    request.integrator = integrator;
    request.scene = scene;
    request.first_seed = seed;
    request.block_sizes = blocks;
    testing::require_agrees_with_pt_mis(request);
}

// bdpt on a furnace whose every pixel is exactly 1: 16 independent runs of `spp` at 32x32, their
// per-pixel means and variances over the runs, one one-sample image test at blocks of 8 (counted
// as 10 convergence tests: alpha / 10, tests/STATISTICS.md rule 2; a run's pixel is already a
// mean of spp x many strategies, so the skewness the rule guards against is small here).
void require_furnace_is_one(const std::string& scene, std::uint64_t first_seed, std::uint64_t spp) {
    constexpr int runs = 16;
    std::vector<Image> images;
    for (int run = 0; run < runs; ++run) {
        const RenderResult result = render_bdpt(scene, first_seed + static_cast<std::uint64_t>(run), spp, 32);
        REQUIRE(result.invalid_samples == 0u);
        images.push_back(result.image);
    }
    const testing::RunStatistics statistics = testing::run_statistics(images);
    const stats::ImageTestResult test = stats::one_sample_image_test(
        statistics.mean, statistics.variance_of_mean, runs, Spectrum(1.0f), 8, stats::convergence_test_alpha / 10.0);
    const std::string name = "bdpt-furnace " + scene;
    if (!test.passed)
        FAIL(name << ": " << test.message << "\nevidence: "
                  << stats::write_evidence(name, test, {{"bdpt", statistics.mean}, {"bdpt-variance", statistics.variance_of_mean}}));
    SUCCEED(name << ": " << test.message);
}

}  // namespace

TEST_CASE("a bdpt image is bit-identical with 1 and 2 threads", "[convergence][determinism][ch04]") {
    const RenderResult one = render_bdpt("cornell-box/scene.json", 5, 3, 40, 1);
    const RenderResult two = render_bdpt("cornell-box/scene.json", 5, 3, 40, 2);
    REQUIRE(one.image.pixel_count() == two.image.pixel_count());
    CHECK(testing::bit_identical(one.image, two.image));
    const RenderResult other = render_bdpt("cornell-box/scene.json", 6, 3, 40, 2);
    CHECK(!testing::bit_identical(one.image, other.image));
}

TEST_CASE("bdpt's weighted strategy images add up to its image (every contribution is in exactly one strategy "
          "image), and its unweighted ones are each an estimate of the same light",
          "[convergence][ch04]") {
    // Deterministic: the same splats, summed per strategy and all together. Paths up to 7
    // segments, so that the images of lengths 1 to 5 and the "longer" one are all used.
    for (const std::string scene : {"cornell-box/scene.json", "material-spheres/scene-environment.json",
                                    "cornell-box/point-and-spot.json"}) {
        const RenderResult result = render_bdpt(scene, 31, 8, 24, 0, true, 7);
        REQUIRE(result.invalid_samples == 0u);
        REQUIRE(!result.extra_images.empty());
        Image sum(result.image.width(), result.image.height());
        int weighted = 0;
        bool longer_used = false;
        for (const auto& [name, image] : result.extra_images) {
            if (name.find("-weighted.exr") == std::string::npos) continue;
            ++weighted;
            for (std::size_t i = 0; i < sum.pixel_count(); ++i) {
                sum[i] += image[i];
                if (name == "longer-weighted.exr" && image[i] != Spectrum(0.0f)) longer_used = true;
            }
        }
        CHECK(weighted == 2 + 3 + 4 + 5 + 6 + 1);  // lengths 1 to 5, then the longer paths
        CHECK(longer_used);
        double largest_difference = 0.0;
        for (std::size_t i = 0; i < sum.pixel_count(); ++i)
            for (int c = 0; c < 3; ++c) {
                // Up to 21 float images summed: a few float roundings of the pixel's value.
                const double tolerance = 1e-5 * std::abs(result.image[i][c]) + 1e-7;
                largest_difference = std::max(largest_difference, std::abs(sum[i][c] - result.image[i][c]) / tolerance);
            }
        INFO(scene << ": largest difference " << largest_difference << " x its tolerance");
        CHECK(largest_difference <= 1.0);
        bool grids = false;
        for (const auto& [name, image] : result.extra_images)
            if (name == "grid-weighted.png") grids = image.width() == 6 * 24 && image.height() == 5 * 24;
        CHECK(grids);
    }
}

TEST_CASE("bdpt matches the closed forms of the furnaces (emission found by every strategy, the environment as "
          "a light-path origin)",
          "[convergence][ch04]") {
    // The closed furnace: Le / (1 - rho) = 1 from inside an emitting, reflecting sphere; the
    // white furnace: a white sphere under a constant environment of 1. 2 one-sample tests, 20
    // convergence tests' worth of alpha.
    require_furnace_is_one("furnace/scene.json", 811, 16);
    require_furnace_is_one("furnace/scene-environment.json", 831, 16);
}

TEST_CASE("bdpt agrees with pt-mis on the Cornell box", "[convergence][ch04]") {
    // 16 bdpt runs of 64 spp against pt-mis at 1024 spp (32x32), blocks of 32 and 8: 2 tests.
    require_bdpt_agrees("bdpt", "cornell-box/scene.json", 901, {32, 8});
}

TEST_CASE("bdpt with the balance heuristic agrees with pt-mis on the Cornell box", "[convergence][ch04]") {
    require_bdpt_agrees("bdpt-balance", "cornell-box/scene.json", 921, {32});  // 1 test
}

TEST_CASE("bdpt agrees with pt-mis on the Cornell box lit by point and spot lights (delta lights)",
          "[convergence][ch04]") {
    require_bdpt_agrees("bdpt", "cornell-box/point-and-spot.json", 941, {8});  // 1 test
}

TEST_CASE("bdpt agrees with pt-mis on veach-mis (glossy plates, lights of every size)", "[convergence][ch04]") {
    require_bdpt_agrees("bdpt", "veach-mis/scene.json", 961, {8});  // 1 test
}

TEST_CASE("bdpt agrees with pt-mis on material-spheres (glass, mirror, gold: delta and glossy vertices)",
          "[convergence][ch04]") {
    require_bdpt_agrees("bdpt", "material-spheres/scene.json", 981, {32, 8});  // 2 tests
}
