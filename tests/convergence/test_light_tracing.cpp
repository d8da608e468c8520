// Chapter 04's light tracing: its images are deterministic, and it converges to the image of the
// camera-path integrators (Veach 1997, section 10.2: light tracing is the t = 1 strategies alone).
#include "freezeray/image.hpp"

#include "evidence.hpp"
#include "image_tests.hpp"
#include "statistics.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cstring>
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

// The mean of every block x block square of `image` (the image's size a multiple of block), as
// an image of blocks; with `variance` the variance of each block mean of independent pixels,
// sum v / B^2.
Image block_means(const Image& image, int block, bool variance = false) {
    Image blocks(image.width() / block, image.height() / block);
    const double pixels = static_cast<double>(block) * block;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            blocks[static_cast<std::size_t>((y / block) * blocks.width() + x / block)] +=
                image[static_cast<std::size_t>(y * image.width() + x)] / static_cast<float>(variance ? pixels * pixels : pixels);
    return blocks;
}

// Light tracing against pt-mis on `scene` (32x32): one blockwise Welch test per block size.
// A splatted pixel is not an average of independent samples (one light path splats into several
// pixels, and pixels of one render are correlated), so the light-tracing side is estimated from
// `runs` independent renders (seeds): each render's block means are one sample, and their mean
// and variance over the renders are exact whatever the correlation inside a render. pt-mis's
// pixels are independent: its block means have variance sum v / B^2, tested with n - 1 degrees
// of freedom (fewer than its true ones: conservative). Each test is Sidak-corrected over blocks
// x 3 channels at convergence_test_alpha.
void require_light_tracing_agrees_with_pt_mis(const std::string& scene, std::uint64_t first_seed,
                                              const std::vector<int>& block_sizes) {
    constexpr int size = 32;
    constexpr int runs = 16;
    constexpr std::uint64_t light_spp = 64;
    const RenderResult reference = render_light_tracing(scene, first_seed, 1024, size, 0, "pt-mis");
    REQUIRE(reference.invalid_samples == 0u);
    std::vector<Image> run_images;
    for (int run = 0; run < runs; ++run) {
        const RenderResult light = render_light_tracing(scene, first_seed + 1 + static_cast<std::uint64_t>(run), light_spp, size);
        REQUIRE(light.invalid_samples == 0u);
        run_images.push_back(light.image);
    }
    for (const int block : block_sizes) {
        std::vector<Image> run_blocks;
        for (const Image& image : run_images) run_blocks.push_back(block_means(image, block));
        // The block images of the runs as samples: their mean and variance of the mean, per block.
        Image mean(run_blocks[0].width(), run_blocks[0].height()), variance(mean.width(), mean.height());
        for (std::size_t i = 0; i < mean.pixel_count(); ++i) {
            for (int c = 0; c < 3; ++c) {
                std::vector<double> values;
                for (const Image& b : run_blocks) values.push_back(b[i][c]);
                const stats::MeanEstimate estimate = stats::estimate_mean(values);
                mean[i][c] = static_cast<float>(estimate.mean);
                variance[i][c] = static_cast<float>(estimate.variance_of_mean);
            }
        }
        const Image reference_mean = block_means(reference.image, block);
        const Image reference_variance = block_means(reference.variance, block, true);
        // The block images are compared pixel by pixel (blocks of 1 of the block images).
        const stats::ImageTestResult test =
            stats::blockwise_welch_test(mean, variance, runs, reference_mean, reference_variance,
                                        reference.samples_per_pixel, 1, stats::convergence_test_alpha);
        const std::string name = "light-tracing-agrees-with-pt-mis " + scene + " blocks " + std::to_string(block);
        if (!test.passed)
            FAIL(name << ": " << test.message << "\nevidence: "
                      << stats::write_evidence(name, test,
                                               {{"light-tracing-blocks", mean},
                                                {"light-tracing-blocks-variance", variance},
                                                {"pt-mis-blocks", reference_mean},
                                                {"pt-mis-blocks-variance", reference_variance}}));
        SUCCEED(name << ": " << test.message);
    }
}

}  // namespace

TEST_CASE("a light-tracing image is bit-identical with 1 and 2 threads", "[convergence][determinism][ch04]") {
    // 40x40 slots (not a multiple of the 64-path work unit) at 6 spp: splats from every work
    // unit land on shared pixels, added in work-unit order whatever thread traced them.
    const RenderResult one = render_light_tracing("cornell-box/scene.json", 99, 6, 40, 1);
    const RenderResult two = render_light_tracing("cornell-box/scene.json", 99, 6, 40, 2);
    REQUIRE(one.image.pixel_count() == two.image.pixel_count());
    CHECK(std::memcmp(one.image.pixels().data(), two.image.pixels().data(), one.image.pixel_count() * sizeof(Spectrum)) == 0);
    CHECK(std::memcmp(one.variance.pixels().data(), two.variance.pixels().data(),
                      one.variance.pixel_count() * sizeof(Spectrum)) == 0);
    CHECK(one.samples_per_pixel == 6u);
    const RenderResult other = render_light_tracing("cornell-box/scene.json", 100, 6, 40, 2);
    CHECK(std::memcmp(one.image.pixels().data(), other.image.pixels().data(), one.image.pixel_count() * sizeof(Spectrum)) != 0);
}

TEST_CASE("light tracing converges to pt-mis's image of the Cornell box (a wrong splat normalisation, a missing "
          "cosine or importance, or a wrong adjoint shows here)",
          "[convergence][ch04]") {
    // The Cornell box is diffuse only, so light tracing finds every path pt-mis finds (Veach 1997,
    // section 10.2). 16 light-tracing renders of 64 spp against one pt-mis render of 1024 spp;
    // blocks of 32 (the whole image: a 3 % error in the scattered light fails it) and 8 (16
    // blocks): 2 tests at convergence_test_alpha (tests/STATISTICS.md).
    require_light_tracing_agrees_with_pt_mis("cornell-box/scene.json", 451, {32, 8});
}

TEST_CASE("light tracing converges to pt-mis's image of the Cornell box lit by a point and a spot light (light "
          "paths from delta positions, the spot's cone)",
          "[convergence][ch04]") {
    // The same comparison with the point and spot lights of chapter 03 beside the area light;
    // blocks of 8 (a wrong cone shows locally): 1 test at convergence_test_alpha.
    require_light_tracing_agrees_with_pt_mis("cornell-box/point-and-spot.json", 471, {8});
}
