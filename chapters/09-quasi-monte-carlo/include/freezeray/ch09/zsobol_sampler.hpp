// The Morton-ordered Sobol sampler: a pixel's error made blue noise by giving neighbouring
// pixels complementary samples (book chapter 09; Ahmed and Wonka, "Screen-Space Blue-Noise
// Diffusion of Monte Carlo Sampling Error via Hierarchical Ordering of Pixels", 2020; Pharr,
// Jakob and Humphreys, "Physically Based Rendering", 4th edition, 2023, section 8.7.7).
#pragma once

#include "freezeray/ch09/joint_sets.hpp"
#include "freezeray/ch09/scrambled_sobol.hpp"
#include "freezeray/ch09/sobol_sampler.hpp"
#include "freezeray/sampler.hpp"

#include <array>
#include <cstdint>

namespace freezeray::ch09 {

// One Sobol sequence for a whole tile of pixels rather than one per pixel. The sequence's
// index is the pixel's Morton code (x and y bits interleaved) followed by the sample's number in
// the pixel, so that each pixel takes one block of 2^L consecutive points, each 2 x 2 quad of
// pixels one block of 4 * 2^L, each 4 x 4 square of them one block of 16 * 2^L, and so on. A
// block from a multiple of its size is a net, so the four pixels of a quad together sample every
// dimension as evenly as 4 * 2^L points can: where one pixel's points fall short of the
// integrand's mean, its neighbours' make up for it, and the image's error moves to high spatial
// frequencies (blue noise), which the eye and any blur see less of.
//
// Randomized as Owen scrambling is, but in base 4 over the pixels: each base-4 digit of the
// Morton code is permuted by one of the 24 permutations of {0, 1, 2, 3}, chosen by a hash of the
// digits above it and the joint set (sampler.hpp), so the quads take their blocks in a random
// order that is different for every set (which decorrelates the sets, as the sobol sampler's
// per-set shuffle does); the sample's number within its pixel is shuffled by a nested scramble,
// so that the first 2^m samples of a pixel are always one block of 2^m points, a net; then every
// coordinate is Owen-scrambled, with one seed for the whole tile per dimension. A set's draws are
// coordinates 0, 1, 2, ... of one point, as in the sobol sampler.
//
// The block size 2^L must be known before the render: it is the planned samples per pixel
// rounded up to a power of two (plan_render). With a time budget or a target error the count is
// not known, L is DefaultEpochLog2 and the quads' blocks are never all rendered: the sampler is
// then a per-pixel Owen-scrambled Sobol sampler like `sobol`, without the blue noise. Samples
// past 2^L (a render continued with --sample-offset) form further epochs of 2^L, each scrambled
// with its own seeds. Tiles are at most 2^10 pixels wide, so that index fits in 32 bits.
class ZSobolSampler final : public Sampler {
public:
    static constexpr int DefaultEpochLog2 = 16;
    static constexpr int MaximumEpochLog2 = 20;

    std::unique_ptr<Sampler> clone() const override { return std::make_unique<ZSobolSampler>(*this); }
    void plan_render(int width, int height, std::uint64_t samples_per_pixel) override;

    // log2 of the samples per pixel of one epoch, and of the tiles' width in pixels.
    int epoch_log2() const { return epoch_log2_; }
    int tile_log2() const { return tile_log2_; }

protected:
    void begin(int x, int y, std::uint32_t pixel_index, std::uint64_t sample_index) override;
    float sample_1d(const Draw& draw) override;
    Vec2 sample_2d(const Draw& draw) override;

private:
    // The sequence index of this sample's draws of the joint set `set`.
    std::uint32_t sequence_index(std::uint32_t set);
    std::uint64_t dimension_key(std::uint32_t dimension) const { return mix_bits(tile_key_ + dimension); }
    float hashed_random(std::uint32_t dimension) const;

    int epoch_log2_ = DefaultEpochLog2;  // L: a pixel's block has 2^L samples
    int tile_log2_ = 10 - 2;             // the Morton code has 2 * tile_log2_ bits
    std::uint64_t tile_key_ = 0;         // (seed, tile, epoch)
    std::uint64_t pixel_key_ = 0;        // (seed, pixel), for the vertices past the quasi-random ones
    std::uint64_t sample_index_ = 0;
    std::uint32_t morton_ = 0;           // the pixel's Morton code within its tile
    std::uint32_t index_in_epoch_ = 0;

    // The pixel's block, per joint set: its digits' permutation depends on the pixel and the set
    // only, so it is computed once for all the samples a pass renders in a pixel.
    struct Block {
        std::uint64_t stamp = 0;
        std::uint32_t start = 0;           // the permuted Morton code, shifted left by L
        std::uint32_t shuffle_seed = 0;    // of the sample's number within the pixel
    };
    std::array<Block, QuasiRandomDimensions> blocks_{};
    std::uint64_t stamp_ = 0;  // which (seed, pixel, epoch) blocks_ holds: a block is valid if its stamp is this
    const SobolNibbleTables* tables_ = joint_coordinate_tables();
    int last_x_ = -1, last_y_ = -1;
    std::uint64_t last_epoch_ = 0, last_seed_ = 0;
};

}  // namespace freezeray::ch09
