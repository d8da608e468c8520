// Splatting integrators (chapter 04) against a per-pixel one: a splatted pixel is not an average
// of independent samples (one light path lands on many pixels), so its error is measured over
// independent renders (seeds) instead of within one.
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/integrator.hpp"

#include <string>
#include <vector>

namespace freezeray::testing {

// The mean of every block x block square of `image` (its size a multiple of block), as an image
// of blocks; with `variance`, the variance of each block mean of independent pixels, sum v / B^2.
Image block_means(const Image& image, int block, bool variance = false);

// Per pixel and channel, the mean of `runs` images and the variance of that mean (the sample
// variance / runs): exact whatever the correlation inside one image.
struct RunStatistics {
    Image mean;
    Image variance_of_mean;
};
RunStatistics run_statistics(const std::vector<Image>& runs);

struct SplattingAgreement {
    std::string integrator;       // the splatting integrator under test
    std::string scene;            // under scenes/
    std::uint64_t first_seed = 1; // the reference uses it (and the next ones), run k uses first_seed + 1000 + k
    int size = 32;                // width and height
    int runs = 16;
    std::uint64_t spp = 64;       // per run
    std::string reference = "pt-mis";
    std::uint64_t reference_spp = 1024;
    // 0: the reference is one render of a per-pixel integrator, with its own variance; > 0: that
    // many independent runs of reference_spp each (a splatting reference, such as bdpt).
    int reference_runs = 0;
    std::uint64_t mlt_bootstrap = 0;  // for mlt runs (0: its default)
    int mlt_chains = 0;
    std::vector<int> block_sizes;  // one blockwise Welch test each, at convergence_test_alpha
};

// Renders `runs` independent images with the integrator and the reference, and REQUIREs (Catch)
// that they agree: for each block size, the block means of the runs (their mean and variance
// over the runs, n = runs) against the reference's block means (a per-pixel reference: variance
// sum v / B^2, with n - 1 degrees of freedom of its samples, fewer than its true ones:
// conservative; a splatting reference: its own runs), each test Sidak-corrected over blocks x 3
// channels at convergence_test_alpha. Every render must be free of invalid samples. Writes
// evidence on failure.
void require_agrees_with_pt_mis(const SplattingAgreement& request);

// The per-pixel mean and variance of the mean of `runs` independent renders (seeds first_seed,
// first_seed + 1, ...), each required free of invalid samples.
RunStatistics render_runs(const std::string& integrator, const std::string& scene, std::uint64_t first_seed, int runs,
                          std::uint64_t spp, int size, std::uint64_t mlt_bootstrap = 0, int mlt_chains = 0);

}  // namespace freezeray::testing
