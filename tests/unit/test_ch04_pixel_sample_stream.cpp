// A bidirectional sample's numbers from the pixel's sampler (chapter 04's PixelSampleStream,
// book chapter 09, "Bidirectional samples"): each stream's draws take the dimensions of its own
// window in the order drawn, a pair two; windows never overlap, and draws past a window's end get
// distinct dimensions beyond them all; with the independent sampler the numbers are the slot's
// own stream's, bit for bit (so bidirectional images are unchanged); with the sobol sampler a
// stream's pair over a pixel's 2^m samples is a (0, m, 2)-net. Deterministic.
#include "freezeray/ch04/pixel_sample_stream.hpp"
#include "freezeray/ch09/sobol_sampler.hpp"
#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch04;

namespace {

// A sampler that answers each draw with its dimension, and records it.
class RecordingSampler final : public Sampler {
public:
    std::unique_ptr<Sampler> clone() const override { return std::make_unique<RecordingSampler>(*this); }
    std::vector<std::uint32_t> dimensions;  // every dimension asked for, a pair's first only

protected:
    void begin(int, int, std::uint32_t, std::uint64_t) override { dimensions.clear(); }
    float sample_1d(const Draw& draw) override {
        dimensions.push_back(draw.dimension);
        return 0.5f;
    }
    Vec2 sample_2d(const Draw& draw) override {
        dimensions.push_back(draw.dimension);
        return Vec2(0.5f);
    }
};

}  // namespace

TEST_CASE("a bidirectional sample's streams draw from their own windows of dimensions", "[unit][ch04][ch09]") {
    RecordingSampler sampler;
    sampler.start_pixel_sample(0, 0, 0, 0);
    PixelSampleStream samples(sampler);
    // The camera stream is current at first: the film position is dimensions 0 and 1.
    samples.next_2d();
    samples.next_float();
    samples.next_2d();
    samples.start_stream(LightStream);
    samples.next_float();
    samples.next_2d();
    samples.start_stream(ConnectionStream);
    samples.next_2d();
    samples.start_stream(CameraStream);  // a stream restarts from its window's start
    samples.next_float();
    const std::uint32_t light = StreamWindows[LightStream].first, connection = StreamWindows[ConnectionStream].first;
    CHECK(sampler.dimensions == std::vector<std::uint32_t>{0, 2, 3, light, light + 1, connection, 0});
}

TEST_CASE("the windows do not overlap, and draws past them take distinct dimensions beyond them", "[unit][ch04][ch09]") {
    for (int stream = 0; stream + 1 < BidirectionalStreamCount; ++stream)
        CHECK(StreamWindows[stream].first + StreamWindows[stream].size <= StreamWindows[stream + 1].first);
    const StreamWindow& last = StreamWindows[BidirectionalStreamCount - 1];
    RecordingSampler sampler;
    sampler.start_pixel_sample(0, 0, 0, 0);
    PixelSampleStream samples(sampler);
    std::set<std::uint32_t> seen;
    for (int stream = 0; stream < BidirectionalStreamCount; ++stream) {
        samples.start_stream(stream);
        // Pairs and singles mixed, far past the window's end; every number's dimension is new.
        for (int draw = 0; draw < 100; ++draw) {
            const std::uint32_t first = samples.take(draw % 3 == 0 ? 1 : 2);
            const std::uint32_t count = draw % 3 == 0 ? 1 : 2;
            const StreamWindow& window = StreamWindows[stream];
            INFO("stream " << stream << ", draw " << draw << ", dimension " << first);
            const bool inside = first >= window.first && first + count <= window.first + window.size;
            CHECK((inside || first >= last.first + last.size));
            CHECK((inside || first >= OverflowDimensions));
            for (std::uint32_t d = first; d < first + count; ++d) CHECK(seen.insert(d).second);
        }
    }
}

TEST_CASE("with the independent sampler a bidirectional sample's numbers are the slot's own stream's", "[unit][ch04][ch09]") {
    // The same pixel stream bidirectional path tracing draws from without a sampler: images stay
    // bit for bit what they were.
    const std::uint64_t seed = 7;
    const std::uint32_t slot = 1234;
    const std::uint64_t sample = 5;
    IndependentSampler sampler;
    sampler.set_seed(seed);
    sampler.start_pixel_sample(static_cast<int>(slot % 64), static_cast<int>(slot / 64), slot, sample);
    PixelSampleStream from_sampler(sampler);
    PCG32 random = make_pixel_stream(seed, slot, sample);
    IndependentSamples independent(random);
    for (int draw = 0; draw < 60; ++draw) {
        if (draw == 20) {
            from_sampler.start_stream(LightStream);
            independent.start_stream(LightStream);
        }
        if (draw % 4 == 1) {
            CHECK(from_sampler.next_float() == independent.next_float());
        } else {
            const Vec2 a = from_sampler.next_2d(), b = independent.next_2d();
            CHECK(a.x == b.x);
            CHECK(a.y == b.y);
        }
    }
}

TEST_CASE("with the sobol sampler a stream's pair over a pixel's samples is a net", "[unit][ch04][ch09]") {
    // The light subpath's point on the light (its second draw, a pair) over 2^8 samples of one
    // pixel, and the second camera vertex's BSDF pair: every elementary interval of area 2^-8
    // holds one point (Sobol dimensions 0 and 1 are a (0, 2)-sequence, chapter 09).
    constexpr int m = 8;
    ch09::SobolSampler sampler;
    sampler.set_seed(3);
    for (const int stream : {LightStream, CameraStream}) {
        std::vector<Vec2> points;
        for (std::uint64_t i = 0; i < (1u << m); ++i) {
            sampler.start_pixel_sample(5, 9, 9 * 16 + 5, i);
            PixelSampleStream samples(sampler);
            samples.start_stream(stream);
            samples.next_float();
            if (stream == CameraStream) {
                samples.next_2d();
                samples.next_float();
            }
            points.push_back(samples.next_2d());
        }
        for (int a = 0; a <= m; ++a) {
            std::vector<int> count(1u << m, 0);
            for (const Vec2& p : points) {
                const auto i = static_cast<std::uint32_t>(std::ldexp(p.x, a));
                const auto j = static_cast<std::uint32_t>(std::ldexp(p.y, m - a));
                ++count[(i << (m - a)) | j];
            }
            INFO("stream " << stream << ", boxes of 2^-" << a << " x 2^-" << (m - a));
            for (const int c : count) REQUIRE(c == 1);
        }
    }
}
