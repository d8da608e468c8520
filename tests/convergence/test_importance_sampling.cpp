// Chapter 02's path tracer agrees with chapter 01's on a scene where both apply.
#include "evidence.hpp"
#include "image_tests.hpp"
#include "statistics.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;

namespace {

// Renders the Cornell box at 32x32 with an integrator; both integrators stop at the same depth
// (64 segments) so that they estimate exactly the same image.
RenderResult render_cornell(const std::string& integrator, std::uint64_t seed, std::uint64_t spp) {
    testing::TestRender request;
    request.scene = testing::scene_path("cornell-box/scene.json");
    request.integrator = integrator;
    request.width = request.height = 32;
    request.samples_per_pixel = spp;
    request.seed = seed;
    request.max_depth = 64;
    return testing::render(request);
}

// Passes, or fails with the evidence (both renders, their variances, the p-value map) on disk.
void require_agreement(const stats::ImageTestResult& test, const RenderResult& naive, const RenderResult& importance) {
    if (!test.passed) {
        const std::string folder = stats::write_evidence(
            "pt-is-agrees-with-pt-naive", test,
            {{"pt-naive", naive.image}, {"pt-naive-variance", naive.variance}, {"pt-is", importance.image},
             {"pt-is-variance", importance.variance}});
        FAIL(test.message << "\nevidence: " << folder);
    }
    SUCCEED(test.message);
}

}  // namespace

TEST_CASE("pt-is agrees with pt-naive on the Cornell box (Russian roulette without reweighting, a wrong pdf or "
          "a missing cosine would not)",
          "[convergence][ch02]") {
    // Two renders with independent seeds, compared twice with Welch's t-test per channel
    // (tests/STATISTICS.md), each at a false-failure rate of 1e-5: over the whole image (one
    // 32x32 block), which detects a global bias, and over 8x8 blocks (Sidak-corrected over 48
    // block-channels), which detects a local one. The scene has no delta lobes, so naive
    // hemisphere sampling sees everything importance sampling does.
    //
    // Power: at 1024 spp the image mean has a relative standard error of about 0.7% (per-pixel
    // relMSE of pt-naive about 0.03, over 1024 pixels), so the whole-image test rejects a bias
    // of 3.5% or more almost surely. Russian roulette without dividing by q loses 8.3% of the
    // light here (measured), far beyond that; the 8x8 blocks alone (about 3% standard error)
    // would miss it.
    const RenderResult naive = render_cornell("pt-naive", 101, 1024);
    const RenderResult importance = render_cornell("pt-is", 202, 1024);
    REQUIRE(naive.invalid_samples == 0u);
    REQUIRE(importance.invalid_samples == 0u);
    for (const int block : {32, 8}) {
        const stats::ImageTestResult test = stats::blockwise_welch_test(
            naive.image, naive.variance, naive.samples_per_pixel, importance.image, importance.variance,
            importance.samples_per_pixel, block, stats::convergence_test_alpha);
        INFO("blocks of " << block << " pixels");
        require_agreement(test, naive, importance);
    }
}

