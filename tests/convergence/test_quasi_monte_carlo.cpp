// Chapter 09's samplers inside the renderer: pt-mis drawing from `sobol`, `zsobol` or `stratified`,
// and bdpt drawing from `sobol`, converge to the same image as pt-mis with independent samples,
// and stay deterministic. A QMC render's per-pixel variance does not measure its error (its samples are not independent), so agreement
// is tested over 16 runs with independent scrambles (seeds), whose spread does. Five tests at
// convergence_test_alpha (tests/STATISTICS.md, label convergence).
#include "independent_runs.hpp"
#include "determinism.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>


using namespace freezeray;

TEST_CASE("pt-mis with the sobol sampler agrees with independent pt-mis on the Cornell box", "[convergence][ch09]") {
    // 16 runs of 64 spp, each its own scramble, against one independent pt-mis render of 1024 spp;
    // block means at 32 x 32 (the whole image) and 8 x 8: 2 tests.
    testing::SplattingAgreement request;
    request.integrator = "pt-mis@sobol";
    request.scene = "cornell-box/scene.json";
    request.first_seed = 901;
    request.block_sizes = {32, 8};
    testing::require_agrees_with_pt_mis(request);
}

TEST_CASE("pt-mis with the stratified sampler agrees with independent pt-mis on the Cornell box", "[convergence][ch09]") {
    // As above, 8 x 8 blocks: 1 test.
    testing::SplattingAgreement request;
    request.integrator = "pt-mis@stratified";
    request.scene = "cornell-box/scene.json";
    request.first_seed = 931;
    request.block_sizes = {8};
    testing::require_agrees_with_pt_mis(request);
}

TEST_CASE("pt-mis with the zsobol sampler agrees with independent pt-mis on the Cornell box", "[convergence][ch09]") {
    // As above, 8 x 8 blocks: 1 test. 64 spp are planned, so each pixel's 64 samples and each
    // aligned square's are blocks of one Sobol sequence (the blue-noise arrangement).
    testing::SplattingAgreement request;
    request.integrator = "pt-mis@zsobol";
    request.scene = "cornell-box/scene.json";
    request.first_seed = 961;
    request.block_sizes = {8};
    testing::require_agrees_with_pt_mis(request);
}

TEST_CASE("bdpt with the sobol sampler agrees with independent pt-mis on the Cornell box", "[convergence][ch09]") {
    // Bidirectional samples drawn from the pixel's sampler (chapter 04's PixelSampleStream): as
    // above, 8 x 8 blocks: 1 test.
    testing::SplattingAgreement request;
    request.integrator = "bdpt@sobol";
    request.scene = "cornell-box/scene.json";
    request.first_seed = 991;
    request.block_sizes = {8};
    testing::require_agrees_with_pt_mis(request);
}

TEST_CASE("a sobol image is bit-identical with 1 and 2 threads", "[convergence][determinism][ch09]") {
    for (const char* integrator : {"pt-mis@sobol", "pt-mis@zsobol", "pt-naive@stratified", "bdpt@sobol", "bdpt@zsobol"}) {
        testing::TestRender request;
        request.scene = testing::scene_path("cornell-box/scene.json");
        request.integrator = integrator;
        request.width = request.height = 40;  // not a multiple of the tile size
        request.samples_per_pixel = 6;
        request.seed = 99;
        testing::check_thread_count_independent(request);
    }
}
