// Jittered (stratified) sampling, the chapter's first step beyond independent numbers (book
// chapter 09; pbrt-v3, section 7.3).
#pragma once

#include "freezeray/sampler.hpp"

#include <cstdint>

namespace freezeray::ch09 {

// A random permutation of 0 .. length - 1 given by its seed, element `index` of it, without
// storing it (Kensler, "Correlated Multi-Jittered Sampling", Pixar technical memo 13-01, 2013).
std::uint32_t permutation_element(std::uint32_t index, std::uint32_t length, std::uint32_t seed);

// Jittered sampling needs to know how many samples it stratifies. A render that may stop at any
// time does not, so the samples of a pixel are stratified in blocks of doubling size, the blocks
// the render's passes make: sample 0, sample 1, samples 2-3, 4-7, ..., 2^k to 2^(k+1) - 1. Within
// a block of n = 2^k samples, a 1D draw takes one of n strata of [0, 1) and a 2D draw one cell of
// a 2^ceil(k/2) x 2^floor(k/2) grid, each sample its own stratum by a permutation seeded per
// (seed, pixel, dimension, block), jittered inside it. Each sample alone is uniform, so
// estimates stay unbiased; a block cut short by the time budget is stratified only in part.
class StratifiedSampler final : public Sampler {
public:
    std::unique_ptr<Sampler> clone() const override { return std::make_unique<StratifiedSampler>(*this); }

protected:
    void begin(int x, int y, std::uint32_t pixel_index, std::uint64_t sample_index) override;
    // Each dimension stratified on its own: a draw's joint set is not read.
    float sample_1d(const Draw& draw) override;
    Vec2 sample_2d(const Draw& draw) override;

private:
    std::uint32_t stratum(std::uint32_t dimension) const;
    float jitter(std::uint32_t dimension) const;

    std::uint64_t pixel_key_ = 0;
    std::uint64_t sample_index_ = 0;
    int block_log2_ = 0;            // the block has 2^block_log2_ samples
    std::uint32_t index_in_block_ = 0;
};

}  // namespace freezeray::ch09
