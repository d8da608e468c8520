// Chapter 04's light tracing: its images are deterministic, and it converges to the image of the
// camera-path integrators (Veach 1997, section 10.2: light tracing is the t = 1 strategies alone).
#include "freezeray/image.hpp"

#include "independent_runs.hpp"
#include "determinism.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <vector>

using namespace freezeray;

namespace {

RenderResult render_light_tracing(const std::string& scene, std::uint64_t seed, std::uint64_t spp, int size,
                                  int threads = 0, const std::string& integrator = "light-tracing") {
    testing::TestRender request;
    request.scene = testing::scene_path(scene);
    request.integrator = integrator;
    request.width = request.height = size;
    request.samples_per_pixel = spp;
    request.seed = seed;
    request.threads = threads;
    request.max_depth = 64;
    return testing::render(request);
}

}  // namespace

TEST_CASE("a light-tracing image is bit-identical with 1 and 2 threads", "[convergence][determinism][ch04]") {
    // 40x40 slots (not a multiple of the 64-path work unit) at 6 spp: splats from every work
    // unit land on shared pixels, added in work-unit order whatever thread traced them.
    const RenderResult one = render_light_tracing("cornell-box/scene.json", 99, 6, 40, 1);
    const RenderResult two = render_light_tracing("cornell-box/scene.json", 99, 6, 40, 2);
    REQUIRE(one.image.pixel_count() == two.image.pixel_count());
    CHECK(testing::bit_identical(one.image, two.image));
    CHECK(testing::bit_identical(one.variance, two.variance));
    CHECK(one.samples_per_pixel == 6u);
    const RenderResult other = render_light_tracing("cornell-box/scene.json", 100, 6, 40, 2);
    CHECK(!testing::bit_identical(one.image, other.image));
}

TEST_CASE("light tracing converges to pt-mis's image of the Cornell box (a wrong splat normalisation, a missing "
          "cosine or importance, or a wrong adjoint shows here)",
          "[convergence][ch04]") {
    // The Cornell box is diffuse only, so light tracing finds every path pt-mis finds (Veach 1997,
    // section 10.2). 16 light-tracing renders of 64 spp against one pt-mis render of 1024 spp;
    // blocks of 32 (the whole image: a 3 % error in the scattered light fails it) and 8 (16
    // blocks): 2 tests at convergence_test_alpha (tests/STATISTICS.md).
    testing::SplattingAgreement request;
    request.integrator = "light-tracing";
    request.scene = "cornell-box/scene.json";
    request.first_seed = 451;
    request.block_sizes = {32, 8};
    testing::require_agrees_with_pt_mis(request);
}

TEST_CASE("light tracing converges to pt-mis's image of the Cornell box lit by a point and a spot light (light "
          "paths from delta positions, the spot's cone)",
          "[convergence][ch04]") {
    // The same comparison with the point and spot lights of chapter 03 beside the area light;
    // blocks of 8 (a wrong cone shows locally): 1 test at convergence_test_alpha.
    testing::SplattingAgreement request;
    request.integrator = "light-tracing";
    request.scene = "cornell-box/point-and-spot.json";
    request.first_seed = 471;
    request.block_sizes = {8};
    testing::require_agrees_with_pt_mis(request);
}
