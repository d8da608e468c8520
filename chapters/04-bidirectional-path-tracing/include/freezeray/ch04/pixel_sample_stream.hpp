// A bidirectional sample's numbers drawn from the pixel's Sampler (book chapter 09,
// "Bidirectional samples"): each of the sample's streams (camera, light, connections) numbers
// its draws from the start of its own window of dimensions, so that a quasi-random sampler gives
// every draw of a pixel's samples its own well-stratified sequence, as it does a path tracer's.
#pragma once

#include "freezeray/ch04/sample_stream.hpp"
#include "freezeray/ch04/subpaths.hpp"
#include "freezeray/sampler.hpp"

#include <cstdint>

namespace freezeray::ch04 {

// The dimensions a stream's draws take, in the order drawn: the camera stream from 0 (its first
// pair, the film position, is dimensions 0 and 1, where the per-pixel integrators place their
// samples in the pixel), the light stream from 64, the connections' from 112. A camera subpath
// draws four numbers a vertex (a BSDF pair, a lobe, a roulette number), a light subpath five
// before its first vertex and four a vertex after it, and a connection to a sampled light point
// three, so paths of up to 15 segments (camera), 10 (light) and 6 connections fit their windows;
// chapter 09's quasi-random samplers answer dimensions 0 to 129.
struct StreamWindow {
    std::uint32_t first, size;
};
inline constexpr StreamWindow StreamWindows[BidirectionalStreamCount] = {{0, 64}, {64, 48}, {112, 16}};
// A draw past its window's end takes a dimension of its own far beyond every window, where the
// quasi-random samplers return hashed independent numbers: deep vertices carry little light.
inline constexpr std::uint32_t OverflowDimensions = 1u << 20;

class PixelSampleStream final : public SampleStream {
public:
    // `sampler` has started the pixel sample (Sampler::start_pixel_sample); the camera stream is
    // current.
    explicit PixelSampleStream(Sampler& sampler) : sampler_(sampler) {}

    float next_float() override { return sampler_.get_1d_at(take(1)); }
    Vec2 next_2d() override { return sampler_.get_2d_at(take(2)); }
    void start_stream(int index) override {
        stream_ = index;
        drawn_ = 0;
    }

    // The dimension of the stream's next draw of `count` numbers (1 or 2), which it then takes.
    std::uint32_t take(std::uint32_t count) {
        const StreamWindow& window = StreamWindows[stream_];
        const std::uint32_t offset = drawn_;
        drawn_ += count;
        if (offset + count <= window.size) return window.first + offset;
        return OverflowDimensions + (static_cast<std::uint32_t>(stream_) << 16) + offset;
    }

private:
    Sampler& sampler_;
    int stream_ = CameraStream;
    std::uint32_t drawn_ = 0;
};

}  // namespace freezeray::ch04
