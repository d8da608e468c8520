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
                           std::uint64_t spp, int size, std::uint64_t mlt_bootstrap = 0, int mlt_chains = 0) {
    TestRender request;
    request.mlt_bootstrap = mlt_bootstrap;
    request.mlt_chains = mlt_chains;
    request.scene = scene_path(scene);
    request.integrator = integrator;
    request.width = request.height = size;
    request.samples_per_pixel = spp;
    request.seed = seed;
    request.max_depth = 64;
    return render(request);
}

}  // namespace

RunStatistics render_runs(const std::string& integrator, const std::string& scene, std::uint64_t first_seed, int runs,
                          std::uint64_t spp, int size, std::uint64_t mlt_bootstrap, int mlt_chains) {
    std::vector<Image> images;
    for (int run = 0; run < runs; ++run) {
        const RenderResult result =
            render_square(integrator, scene, first_seed + static_cast<std::uint64_t>(run), spp, size, mlt_bootstrap, mlt_chains);
        REQUIRE(result.invalid_samples == 0u);
        images.push_back(result.image);
    }
    return run_statistics(images);
}

void require_agrees_with_pt_mis(const SplattingAgreement& r) {
    // The reference: one per-pixel render (seed first_seed), or independent runs (seeds
    // first_seed + 10000 + k) of a splatting integrator.
    Image reference_image, reference_variance_image;
    std::vector<Image> reference_runs;
    std::uint64_t reference_samples = static_cast<std::uint64_t>(r.reference_runs);
    if (r.reference_runs == 0) {
        const RenderResult reference = render_square(r.reference, r.scene, r.first_seed, r.reference_spp, r.size);
        REQUIRE(reference.invalid_samples == 0u);
        reference_image = reference.image;
        reference_variance_image = reference.variance;
        reference_samples = reference.samples_per_pixel;
    } else {
        for (int run = 0; run < r.reference_runs; ++run) {
            const RenderResult result = render_square(r.reference, r.scene, r.first_seed + 10000 + static_cast<std::uint64_t>(run),
                                                      r.reference_spp, r.size);
            REQUIRE(result.invalid_samples == 0u);
            reference_runs.push_back(result.image);
        }
    }
    std::vector<Image> run_images;
    for (int run = 0; run < r.runs; ++run) {
        const RenderResult result = render_square(r.integrator, r.scene, r.first_seed + 1 + static_cast<std::uint64_t>(run),
                                                  r.spp, r.size, r.mlt_bootstrap, r.mlt_chains);
        REQUIRE(result.invalid_samples == 0u);
        run_images.push_back(result.image);
    }
    for (const int block : r.block_sizes) {
        std::vector<Image> run_blocks;
        for (const Image& image : run_images) run_blocks.push_back(block_means(image, block));
        const RunStatistics runs = run_statistics(run_blocks);
        // Within one run pixels are correlated, so block variances come from the runs' block
        // means; a per-pixel reference's pixels are independent (sum v / B^2).
        Image reference_mean, reference_variance;
        if (reference_runs.empty()) {
            reference_mean = block_means(reference_image, block);
            reference_variance = block_means(reference_variance_image, block, true);
        } else {
            std::vector<Image> reference_blocks;
            for (const Image& image : reference_runs) reference_blocks.push_back(block_means(image, block));
            const RunStatistics statistics = run_statistics(reference_blocks);
            reference_mean = statistics.mean;
            reference_variance = statistics.variance_of_mean;
        }
        // The block images are compared pixel by pixel (blocks of 1 of the block images).
        const stats::ImageTestResult test =
            stats::blockwise_welch_test(runs.mean, runs.variance_of_mean, static_cast<std::uint64_t>(r.runs),
                                        reference_mean, reference_variance, reference_samples, 1,
                                        stats::convergence_test_alpha);
        const std::string name = r.integrator + "-agrees-with-" + r.reference + " " + r.scene + " blocks " + std::to_string(block);
        if (!test.passed)
            FAIL(name << ": " << test.message << "\nevidence: "
                      << stats::write_evidence(name, test,
                                               {{r.integrator + "-blocks", runs.mean},
                                                {r.integrator + "-blocks-variance", runs.variance_of_mean},
                                                {r.reference + "-blocks", reference_mean},
                                                {r.reference + "-blocks-variance", reference_variance}}));
        SUCCEED(name << ": " << test.message);
    }
}

}  // namespace freezeray::testing
