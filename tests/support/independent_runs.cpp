// Splatting integrators against pt-mis, over independent runs.
#include "independent_runs.hpp"

#include "evidence.hpp"
#include "image_tests.hpp"
#include "statistics.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

namespace freezeray::testing {

Image block_means(const Image& image, int block, bool variance) {
    Image blocks(image.width() / block, image.height() / block);
    const double pixels = static_cast<double>(block) * block;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            blocks[static_cast<std::size_t>((y / block) * blocks.width() + x / block)] +=
                image[static_cast<std::size_t>(y * image.width() + x)] / static_cast<float>(variance ? pixels * pixels : pixels);
    return blocks;
}

RunStatistics run_statistics(const std::vector<Image>& runs) {
    RunStatistics result{Image(runs[0].width(), runs[0].height()), Image(runs[0].width(), runs[0].height())};
    for (std::size_t i = 0; i < result.mean.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            std::vector<double> values;
            for (const Image& image : runs) values.push_back(image[i][c]);
            const stats::MeanEstimate estimate = stats::estimate_mean(values);
            result.mean[i][c] = static_cast<float>(estimate.mean);
            result.variance_of_mean[i][c] = static_cast<float>(estimate.variance_of_mean);
        }
    return result;
}

namespace {

RenderResult render_square(const std::string& integrator, const std::string& scene, std::uint64_t seed,
                           std::uint64_t spp, int size) {
    TestRender request;
    request.scene = scene_path(scene);
    request.integrator = integrator;
    request.width = request.height = size;
    request.samples_per_pixel = spp;
    request.seed = seed;
    request.max_depth = 64;
    return render(request);
}

}  // namespace

void require_agrees_with_pt_mis(const SplattingAgreement& r) {
    const RenderResult reference = render_square("pt-mis", r.scene, r.first_seed, r.reference_spp, r.size);
    REQUIRE(reference.invalid_samples == 0u);
    std::vector<Image> run_images;
    for (int run = 0; run < r.runs; ++run) {
        const RenderResult result =
            render_square(r.integrator, r.scene, r.first_seed + 1 + static_cast<std::uint64_t>(run), r.spp, r.size);
        REQUIRE(result.invalid_samples == 0u);
        run_images.push_back(result.image);
    }
    for (const int block : r.block_sizes) {
        std::vector<Image> run_blocks;
        for (const Image& image : run_images) run_blocks.push_back(block_means(image, block));
        const RunStatistics runs = run_statistics(run_blocks);
        const Image reference_mean = block_means(reference.image, block);
        const Image reference_variance = block_means(reference.variance, block, true);
        // The block images are compared pixel by pixel (blocks of 1 of the block images).
        const stats::ImageTestResult test =
            stats::blockwise_welch_test(runs.mean, runs.variance_of_mean, static_cast<std::uint64_t>(r.runs),
                                        reference_mean, reference_variance, reference.samples_per_pixel, 1,
                                        stats::convergence_test_alpha);
        const std::string name = r.integrator + "-agrees-with-pt-mis " + r.scene + " blocks " + std::to_string(block);
        if (!test.passed)
            FAIL(name << ": " << test.message << "\nevidence: "
                      << stats::write_evidence(name, test,
                                               {{r.integrator + "-blocks", runs.mean},
                                                {r.integrator + "-blocks-variance", runs.variance_of_mean},
                                                {"pt-mis-blocks", reference_mean},
                                                {"pt-mis-blocks-variance", reference_variance}}));
        SUCCEED(name << ": " << test.message);
    }
}

}  // namespace freezeray::testing
