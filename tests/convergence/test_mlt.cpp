// Chapter 05's Metropolis light transport: deterministic images, the bootstrap's normalisation
// against bdpt's mean image luminance, and agreement with bdpt on the Cornell box, cornell-lamp
// and door-ajar over independent runs (both sides: 16 runs each; each chain run is correlated
// within itself, the runs are not). Statistical tests at convergence_test_alpha (label
// convergence, tests/STATISTICS.md): 2 + 2 + 1 blockwise Welch tests of mlt, 3 of multiplexed mlt, and
// 1 Welch test.
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/ch05/metropolis_light_transport.hpp"

#include "independent_runs.hpp"
#include "statistics.hpp"
#include "determinism.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>


using namespace freezeray;

namespace {

// Small enough for tests: 20000 bootstrap paths and 128 chains at 32x32 (1024 pixels: 8
// mutations per chain and round).
constexpr std::uint64_t TestBootstrap = 20000;
constexpr int TestChains = 128;

void require_mlt_agrees_with_bdpt(const std::string& scene, std::uint64_t seed, const std::vector<int>& blocks,
                                  const std::string& integrator = "mlt") {
    testing::SplattingAgreement request;
    request.integrator = integrator;
    request.scene = scene;
    request.first_seed = seed;
    request.spp = 64;  // mutations per pixel
    request.reference = "bdpt";
    request.reference_runs = 16;
    request.reference_spp = 64;
    request.mlt_bootstrap = TestBootstrap;
    request.mlt_chains = TestChains;
    request.block_sizes = blocks;
    testing::require_agrees_with_pt_mis(request);
}

}  // namespace

TEST_CASE("an mlt image is bit-identical with 1 and 2 threads", "[convergence][determinism][ch05]") {
    testing::TestRender request;
    request.scene = testing::scene_path("cornell-box/scene.json");
    request.integrator = "mlt";
    request.width = request.height = 40;
    request.samples_per_pixel = 4;
    request.seed = 12;
    request.mlt_bootstrap = 5000;
    request.mlt_chains = 64;
    testing::check_thread_count_independent(request);
}

TEST_CASE("mlt's bootstrap estimate of b equals bdpt's mean image luminance within their standard errors",
          "[convergence][ch05]") {
    // b is the integral of I(u) = the sum of a bidirectional sample's luminances over primary
    // sample space; with the splatting film's normalisation that is the image's mean luminance.
    // One Welch test: b from 200000 bootstrap paths (its standard error from their spread)
    // against the mean luminance of 16 independent bdpt renders (one value per render).
    SceneLoadOptions options;
    options.width = options.height = 32;
    const Scene scene = load_scene(testing::scene_path("cornell-box/scene.json"), testing::full_registry(), options);
    const ch03::FixedLightSampler lights(scene.lights, ch03::LightSelection::Power);
    ch05::MltSettings settings;
    settings.bootstrap_samples = 200000;
    const ch04::BidirectionalSettings bidirectional{64, ch03::MisHeuristic::Power, ""};
    const ch05::Bootstrap bootstrap = ch05::run_bootstrap(scene, lights, bidirectional, settings, 77, 0);

    std::vector<double> run_luminances;
    for (int run = 0; run < 16; ++run) {
        testing::TestRender request;
        request.scene = testing::scene_path("cornell-box/scene.json");
        request.integrator = "bdpt";
        request.width = request.height = 32;
        request.samples_per_pixel = 64;
        request.seed = 7700 + static_cast<std::uint64_t>(run);
        request.max_depth = 64;
        const RenderResult result = testing::render(request);
        double sum = 0.0;
        for (const Spectrum& p : result.image.pixels()) sum += luminance(p);
        run_luminances.push_back(sum / static_cast<double>(result.image.pixel_count()));
    }
    const stats::MeanEstimate bdpt = stats::estimate_mean(run_luminances);
    const stats::MeanEstimate b{bootstrap.b, bootstrap.standard_error * bootstrap.standard_error,
                                static_cast<double>(settings.bootstrap_samples - 1)};
    const stats::TestResult test = stats::welch_t_test(b, bdpt, stats::convergence_test_alpha);
    INFO(test.message);
    CHECK(test.passed);
    CHECK(bootstrap.standard_error < 0.01 * bootstrap.b);  // 200000 paths pin b to better than 1 %
}

TEST_CASE("mlt agrees with bdpt on the Cornell box", "[convergence][ch05]") {
    require_mlt_agrees_with_bdpt("cornell-box/scene.json", 1101, {32, 8});  // 2 tests
}

TEST_CASE("mlt agrees with bdpt on cornell-lamp (light after a bounce off the ceiling)", "[convergence][ch05]") {
    require_mlt_agrees_with_bdpt("cornell-lamp/scene.json", 1201, {32, 8});  // 2 tests
}

TEST_CASE("mlt agrees with bdpt on door-ajar (light only through a crack)", "[convergence][ch05]") {
    require_mlt_agrees_with_bdpt("door-ajar/scene.json", 1301, {32});  // 1 test
}

TEST_CASE("multiplexed mlt agrees with bdpt on the Cornell box and on caustic", "[convergence][ch05]") {
    // Each run's b comes from 20000 bootstrap paths spread over 64 path lengths (a few per cent
    // of error, part of the runs' spread). 3 tests.
    require_mlt_agrees_with_bdpt("cornell-box/scene.json", 1401, {32, 8}, "mlt-multiplexed");
    require_mlt_agrees_with_bdpt("caustic/scene.json", 1501, {32}, "mlt-multiplexed");
}
