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

// Where a draw sits among a pixel sample's numbers. Every draw has its own dimension. It also
// belongs to a joint set: a quasi-Monte Carlo sampler gives the draws of one set as coordinates of
// one point of its sequence, so that they are stratified together, not only each on its own, and
// draws of different sets independently of each other (book chapter 09, "Drawing jointly"). A
// set is named by its first dimension. Samplers that stratify nothing jointly (independent,
// stratified) read the dimension only.
struct DrawPlace {
    std::uint32_t dimension;   // the draw's (a pair's: dimension and dimension + 1)
    std::uint32_t set;         // the first dimension of the draw's joint set
    std::uint32_t coordinate;  // the draw's in the set's point (a pair's: coordinate and coordinate + 1)
    friend constexpr bool operator==(const DrawPlace&, const DrawPlace&) = default;
};
// The most coordinates a joint set's points have.
constexpr std::uint32_t MaxJointCoordinates = 15;

// The path set: from vertex 1's BSDF sample, every draw up to vertex JointPathVertices's BSDF
// sample is one point. Light reaching the camera after a bounce is a function of vertex 1's BSDF
// direction and of the next vertex's light sample together: stratified jointly, the points of
// the second cover the light from every stratum of the first (book chapter 09, "Drawing jointly").
constexpr int JointPathVertices = 3;
constexpr std::uint32_t PathSet = CameraDimensions + static_cast<std::uint32_t>(VertexDimension::BsdfDirection);

// A draw's place in the per-vertex layout:
// - vertex 1 to JointPathVertices: their BSDF draws and the light draws of vertices 2 on are in
//   the path set, at the coordinates of the table below; vertex 1's light sample is a set of its
//   own (position: coordinates 0 and 1, choice: 2), drawn jointly so that the samples that choose
//   one light still cover it evenly;
// - deeper vertices: the light sample is a set (position 0 and 1, choice 2), the BSDF sample is
//   one (direction 0 and 1, lobe 2);
// - Russian roulette is always a set of its own.
// A set's coordinates are numbered by importance: vertex 1's direction first, then vertex 2's
// light sample, whose light depends on it most. A quasi-Monte Carlo sampler gives the first
// coordinates its best-stratified dimensions (chapter 09's JointCoordinateDimension).
constexpr DrawPlace vertex_draw_place(int vertex, VertexDimension d) {
    const std::uint32_t first = CameraDimensions + DimensionsPerVertex * static_cast<std::uint32_t>(vertex - 1);
    const std::uint32_t dimension = first + static_cast<std::uint32_t>(d);
    const std::uint32_t light_set = first + static_cast<std::uint32_t>(VertexDimension::LightPosition);
    const std::uint32_t bsdf_set = first + static_cast<std::uint32_t>(VertexDimension::BsdfDirection);
    // Path-set coordinates of vertices 1 to 3: light position, light choice, BSDF direction,
    // BSDF lobe (vertex 1's light entries are not used: its light sample is a set of its own).
    constexpr std::uint32_t path_coordinates[JointPathVertices][4] = {{0, 0, 0, 12}, {2, 6, 4, 13}, {7, 11, 9, 14}};
    const bool in_path = vertex >= 1 && vertex <= JointPathVertices;
    const std::uint32_t* path = in_path ? path_coordinates[vertex - 1] : nullptr;
    switch (d) {
        case VertexDimension::LightPosition:
            return in_path && vertex > 1 ? DrawPlace{dimension, PathSet, path[0]} : DrawPlace{dimension, light_set, 0};
        case VertexDimension::LightChoice:
            return in_path && vertex > 1 ? DrawPlace{dimension, PathSet, path[1]} : DrawPlace{dimension, light_set, 2};
        case VertexDimension::BsdfDirection:
            return in_path ? DrawPlace{dimension, PathSet, path[2]} : DrawPlace{dimension, bsdf_set, 0};
        case VertexDimension::BsdfLobe:
            return in_path ? DrawPlace{dimension, PathSet, path[3]} : DrawPlace{dimension, bsdf_set, 2};
        case VertexDimension::Roulette: break;
    }
    return DrawPlace{dimension, dimension, 0};
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
    Vec2 pixel_2d() { return sample_2d(DrawPlace{0, 0, 0}); }

    // Moves to the dimensions of path vertex `vertex` (1 = the camera ray's hit).
    void start_vertex(int vertex) { vertex_ = vertex; }
    float get_1d(VertexDimension d) { return sample_1d(vertex_draw_place(vertex_, d)); }
    Vec2 get_2d(VertexDimension d) { return sample_2d(vertex_draw_place(vertex_, d)); }
    // The number, or pair, at an explicit dimension, a set of its own, for an integrator whose
    // draws do not follow the per-vertex layout (chapter 04's bidirectional samples,
    // sample_stream.hpp, lay out their own). A pair takes `dimension` and `dimension + 1`.
    float get_1d_at(std::uint32_t dimension) { return sample_1d(DrawPlace{dimension, dimension, 0}); }
    Vec2 get_2d_at(std::uint32_t dimension) { return sample_2d(DrawPlace{dimension, dimension, 0}); }

protected:
    virtual void begin(int x, int y, std::uint32_t pixel_index, std::uint64_t sample_index) = 0;
    // The number, or pair, at `place`.
    virtual float sample_1d(const DrawPlace& place) = 0;
    virtual Vec2 sample_2d(const DrawPlace& place) = 0;

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
    float sample_1d(const DrawPlace&) override { return random_.next_float(); }
    // The second coordinate is drawn first: the order in which g++ evaluated the arguments of
    // Vec2(random.next_float(), random.next_float()) in the chapters' code before there were
    // samplers, kept so that their images stay bit for bit what they were.
    Vec2 sample_2d(const DrawPlace&) override {
        const float second = random_.next_float();
        const float first = random_.next_float();
        return Vec2(first, second);
    }

private:
    PCG32 random_;
};

}  // namespace freezeray
