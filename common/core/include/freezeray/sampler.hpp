// Samplers: where a camera path's random numbers come from (book chapter 09). Every per-pixel
// integrator draws its numbers from a Sampler, by dimension: the independent sampler (PCG32,
// what chapters 01 to 08 use) ignores the dimension, a quasi-Monte Carlo sampler (chapter 09)
// gives every dimension its own well-stratified sequence over a pixel's samples.
#pragma once

#include "freezeray/cache_line_allocator.hpp"
#include "freezeray/math.hpp"
#include "freezeray/random.hpp"

#include <cstdint>
#include <memory>

namespace freezeray {

// The fixed layout of one pixel sample's dimensions (book chapter 09, "the dimension layout").
// Dimensions 0 and 1 place the sample in the pixel. Path vertex k (k = 1 where the camera ray
// lands) owns the DimensionsPerVertex dimensions from CameraDimensions + DimensionsPerVertex (k - 1),
// and draws each of its numbers at a fixed offset there, so that a vertex that skips its light
// sample (a mirror) does not shift the dimensions of the vertices after it.
enum class VertexDimension : std::uint32_t {
    LightChoice = 0,    // which light to sample (1D)
    LightPosition = 1,  // where on it (2D: offsets 1 and 2)
    BsdfDirection = 3,  // the BSDF's direction (2D: offsets 3 and 4)
    BsdfLobe = 5,       // which lobe of a BSDF with several (1D)
    Roulette = 6,       // Russian roulette (1D); offset 7 is spare
};
constexpr std::uint32_t CameraDimensions = 2;
constexpr std::uint32_t DimensionsPerVertex = 8;

// One draw of a pixel sample: its dimension (a pair's: dimension and dimension + 1), and when it
// belongs to the per-vertex layout, the vertex and what it is there. A sampler that stratifies
// draws jointly (chapter 09's joint sets, joint_sets.hpp) reads the vertex and the role; the
// others read the dimension only. Vertex 0: not of the per-vertex layout (the position in the
// pixel, a dimension an integrator lays out itself).
struct Draw {
    std::uint32_t dimension;
    int vertex = 0;
    VertexDimension role = VertexDimension::LightChoice;
};

// Vertex `vertex`'s draw `d`: at a fixed offset in the vertex's dimensions.
constexpr Draw vertex_draw(int vertex, VertexDimension d) {
    return Draw{CameraDimensions + DimensionsPerVertex * static_cast<std::uint32_t>(vertex - 1) + static_cast<std::uint32_t>(d),
                vertex, d};
}

// Each render thread has its own sampler and writes to it on every draw. Aligned to a cache line
// (and so a whole number of lines long), two threads' samplers never share a line, and one
// thread's writes never take away a line the other is reading ("false sharing"): with two
// threads on the Cornell box, chapter 09's sobol sampler's clones, adjacent on the heap, made a
// render take about 1.3 times as long as it does now (book chapter 09, "Two threads, one cache
// line").
class alignas(CacheLineBytes) Sampler {
public:
    virtual ~Sampler() = default;

    // A sampler for another thread: the same sequence, its own position in it.
    virtual std::unique_ptr<Sampler> clone() const = 0;

    // The render's seed: samplers with different seeds give independent images.
    void set_seed(std::uint64_t seed) { seed_ = seed; }
    std::uint64_t seed() const { return seed_; }

    // Told once before a render: the image's size and how many samples each pixel will get (0 when
    // a time budget or a target error decides). Only a sampler that spreads a pixel's samples
    // over its neighbours needs it (chapter 09's zsobol); the others ignore it.
    virtual void plan_render(int /*width*/, int /*height*/, std::uint64_t /*samples_per_pixel*/) {}

    // Begins sample `sample_index` of pixel (x, y) (`pixel_index` = y * width + x). What is drawn
    // until the next call depends on the seed, the pixel, the sample index and the dimension
    // only, never on the thread or the order in which pixels are rendered.
    void start_pixel_sample(int x, int y, std::uint32_t pixel_index, std::uint64_t sample_index) {
        vertex_ = 1;
        begin(x, y, pixel_index, sample_index);
    }

    // The sample's position in its pixel (dimensions 0 and 1).
    Vec2 pixel_2d() { return sample_2d(Draw{0}); }

    // Moves to the dimensions of path vertex `vertex` (1 = the camera ray's hit).
    void start_vertex(int vertex) { vertex_ = vertex; }
    float get_1d(VertexDimension d) { return sample_1d(vertex_draw(vertex_, d)); }
    Vec2 get_2d(VertexDimension d) { return sample_2d(vertex_draw(vertex_, d)); }
    // The number, or pair, at an explicit dimension, a set of its own, for an integrator whose
    // draws do not follow the per-vertex layout (chapter 04's bidirectional samples,
    // sample_stream.hpp, lay out their own). A pair takes `dimension` and `dimension + 1`.
    float get_1d_at(std::uint32_t dimension) { return sample_1d(Draw{dimension}); }
    Vec2 get_2d_at(std::uint32_t dimension) { return sample_2d(Draw{dimension}); }

protected:
    virtual void begin(int x, int y, std::uint32_t pixel_index, std::uint64_t sample_index) = 0;
    // The number, or pair, of `draw`.
    virtual float sample_1d(const Draw& draw) = 0;
    virtual Vec2 sample_2d(const Draw& draw) = 0;

private:
    std::uint64_t seed_ = 0;
    int vertex_ = 1;
};

// Independent uniform numbers: one PCG32 stream per pixel sample (random.hpp), drawn in the
// order the integrator asks for them; the dimension is ignored. The images of chapters 01 to 08.
class IndependentSampler final : public Sampler {
public:
    std::unique_ptr<Sampler> clone() const override { return std::make_unique<IndependentSampler>(*this); }

protected:
    void begin(int, int, std::uint32_t pixel_index, std::uint64_t sample_index) override {
        random_ = make_pixel_stream(seed(), pixel_index, sample_index);
    }
    float sample_1d(const Draw&) override { return random_.next_float(); }
    // The second coordinate is drawn first: the order in which g++ evaluated the arguments of
    // Vec2(random.next_float(), random.next_float()) in the chapters' code before there were
    // samplers, kept so that their images stay bit for bit what they were.
    Vec2 sample_2d(const Draw&) override {
        const float second = random_.next_float();
        const float first = random_.next_float();
        return Vec2(first, second);
    }

private:
    PCG32 random_;
};

}  // namespace freezeray
