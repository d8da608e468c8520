// The Owen-scrambled Sobol sampler (book chapter 09; Burley, "Practical Hash-based Owen
// Scrambling", JCGT 9(4), 2020).
#pragma once

#include "freezeray/sampler.hpp"

#include <cstdint>

namespace freezeray::ch09 {

// Vertices up to this one draw quasi-random numbers; deeper ones, whose light is a small part of
// the image and where stratification no longer shows, draw hashed independent numbers.
constexpr int QuasiRandomVertices = 16;
constexpr std::uint32_t QuasiRandomDimensions = CameraDimensions + DimensionsPerVertex * QuasiRandomVertices;

// Every 1D or 2D draw is the first one or two dimensions of the Sobol sequence (which together
// are a (0, 2)-sequence: every 2^m consecutive points from a multiple of 2^m stratify the
// unit square in every way a 2^m-point set can), at the pixel sample's index shuffled, each
// coordinate Owen-scrambled; shuffle and scrambles are seeded by (seed, pixel, dimension). So
// each dimension pair is stratified over a pixel's samples on its own, and different pairs, and
// different pixels, are independent of each other: the padding of Kollig and Keller ("Efficient
// multidimensional sampling", 2002). The shuffle is itself a nested scramble of the index, so the
// first 2^m samples of a pixel are always 2^m points of a net, whatever m: renders may stop at any
// time and be resumed.
class SobolSampler final : public Sampler {
public:
    std::unique_ptr<Sampler> clone() const override { return std::make_unique<SobolSampler>(*this); }

protected:
    void begin(int x, int y, std::uint32_t pixel_index, std::uint64_t sample_index) override;
    float sample_1d(std::uint32_t dimension) override;
    Vec2 sample_2d(std::uint32_t dimension) override;

private:
    std::uint64_t dimension_key(std::uint32_t dimension) const;
    float hashed_random(std::uint32_t dimension) const;
    // The pixel's sample index shuffled for the dimension whose key this is.
    std::uint32_t shuffled_index(std::uint64_t key) const;

    std::uint64_t pixel_key_ = 0;
    std::uint64_t sample_index_ = 0;
    std::uint32_t reversed_sample_index_ = 0;  // the low 32 bits of sample_index_, reversed
};

}  // namespace freezeray::ch09
