// The Owen-scrambled Sobol sampler (book chapter 09; Burley, "Practical Hash-based Owen
// Scrambling", JCGT 9(4), 2020).
#pragma once

#include "freezeray/ch09/joint_sets.hpp"
#include "freezeray/ch09/scrambled_sobol.hpp"
#include "freezeray/sampler.hpp"

#include <array>
#include <cstdint>

namespace freezeray::ch09 {

// Vertices up to this one draw quasi-random numbers; deeper ones, whose light is a small part of
// the image and where stratification no longer shows, draw hashed independent numbers.
constexpr int QuasiRandomVertices = 16;
constexpr std::uint32_t QuasiRandomDimensions = CameraDimensions + DimensionsPerVertex * QuasiRandomVertices;

// Every draw is one or two coordinates of a point of the Sobol sequence: the point at the pixel
// sample's index shuffled, each coordinate Owen-scrambled. The shuffle is seeded by (seed, pixel,
// the draw's joint set), each scramble by (seed, pixel, the draw's dimension). A set's draws take
// coordinates 0, 1, 2, ... of one point, from the Sobol dimensions JointCoordinateDimension gives
// (scrambled_sobol.hpp); every set's first pair is Sobol dimensions 0 and 1, which together are a
// (0, 2)-sequence: every 2^m consecutive points from a multiple of 2^m stratify the unit square
// in every way a 2^m-point set can. So each set is stratified over a pixel's samples, and
// different sets, and different pixels, are independent of each other: the padding of Kollig and Keller ("Efficient multidimensional
// sampling", 2002), by sets rather than by pairs. The shuffle is itself a nested scramble of the
// index, so the first 2^m samples of a pixel are always 2^m points of a net, whatever m: renders
// may stop at any time and be resumed.
class SobolSampler final : public Sampler {
public:
    std::unique_ptr<Sampler> clone() const override { return std::make_unique<SobolSampler>(*this); }

protected:
    void begin(int x, int y, std::uint32_t pixel_index, std::uint64_t sample_index) override;
    float sample_1d(const Draw& draw) override;
    Vec2 sample_2d(const Draw& draw) override;

private:
    // The hash of (seed, pixel, dimension) that seeds the dimension's scramble and, for a set's
    // first dimension, the set's shuffle.
    std::uint64_t dimension_key(std::uint32_t dimension);
    float hashed_random(std::uint32_t dimension);
    // The pixel's sample index shuffled for the joint set `set`, its bits reversed.
    std::uint32_t reversed_shuffled_index(std::uint32_t set);

    std::uint64_t pixel_key_ = 0;
    std::uint64_t sample_index_ = 0;
    std::uint32_t reversed_sample_index_ = 0;  // the low 32 bits of sample_index_, reversed
    // Each set's shuffled index, valid for the sample whose stamp it carries.
    struct ShuffledIndex {
        std::uint64_t stamp = 0;
        std::uint32_t reversed_index = 0;
    };
    std::array<ShuffledIndex, QuasiRandomDimensions> shuffled_{};
    std::uint64_t sample_stamp_ = 0;
    // Each dimension's key, valid for the pixel whose stamp it carries: a render's pass takes a
    // pixel's samples one after another, and they share their keys.
    struct DimensionKey {
        std::uint64_t stamp = 0;
        std::uint64_t key = 0;
    };
    std::array<DimensionKey, QuasiRandomDimensions> keys_{};
    std::uint64_t pixel_stamp_ = 0;
    std::uint32_t last_pixel_index_ = 0;
    std::uint64_t last_seed_ = 0;
    const SobolNibbleTables* tables_ = joint_coordinate_tables();
};

}  // namespace freezeray::ch09
