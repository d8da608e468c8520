// The splatting film: contributions that land on any pixel, from light paths (light tracing and,
// later, bidirectional path tracing's t = 1 strategies; Veach 1997, section 10.2; pbrt-v3,
// chapter 16). Its image is bit-identical for a given seed whatever the thread count.
#pragma once

#include "freezeray/cache_line_allocator.hpp"
#include "freezeray/film.hpp"
#include "freezeray/image.hpp"
#include "freezeray/math.hpp"

#include <cstdint>
#include <vector>

namespace freezeray::ch04 {

// BOOK(splat-buffer)
// The splats of one work unit (a run of consecutive light paths), in the order they were made.
// Determinism: floating-point addition is not associative, so adding splats to shared pixels
// from several threads (atomics, locks) would give results that depend on the interleaving. A
// work unit instead records its splats here; after each batch the film adds the buffers in work
// unit order (SplatFilm::add), so every pixel sees the same additions in the same order for any
// thread count. Fixed-point integer atomics would also be order-independent, but need a range
// fixed in advance, and light tracing's splats have no useful bound (We grows like 1/cos^4 at the
// film's corners, 1/r^2 near the lights). Neighbouring work units run at the same time on
// different threads, so each buffer starts on a cache line of its own (see Sampler).
class alignas(CacheLineBytes) SplatBuffer {
public:
    struct Splat {
        std::uint32_t pixel;  // y * width + x
        std::uint16_t half;   // which half-buffer (the light path's index, even or odd)
        std::uint16_t layer;  // 0: the image; 1...: extra images (bidirectional strategy images)
        Spectrum value;
    };

    SplatBuffer(int width, int height) : width_(width), height_(height) {}

    // Starts light path number `path_index` (the splats that follow are its own): its parity
    // chooses the half-buffer used for the error estimate.
    void begin_light_path(std::uint64_t path_index) {
        half_ = static_cast<std::uint16_t>(path_index & 1u);
        ++paths_[half_];
    }
    // Adds `value` to the pixel containing film position raster_position (pixels, as
    // Camera::generate_ray). Positions outside the film are ignored.
    void add_splat(const Vec2& raster_position, const Spectrum& value) { add_splat(raster_position, value, 0); }
    // The same into extra image `layer` (>= 1) of a film made with that many extra layers; such
    // splats do not count in the image or its error estimate.
    void add_splat(const Vec2& raster_position, const Spectrum& value, int layer);
    void clear();

    const std::vector<Splat>& splats() const { return splats_; }
    std::uint64_t light_paths(int half) const { return paths_[half]; }

private:
    int width_, height_;
    std::uint16_t half_ = 0;
    std::uint64_t paths_[2] = {0, 0};
    std::vector<Splat> splats_;
};
// END BOOK

// BOOK(splat-film)
// Sums of splats in two half-buffers (light paths of even and of odd index).
// Normalisation: a pixel's value is the sum of its splats divided by the number of light paths
// per pixel (all light paths / pixel count), which is the sample count per pixel of a light
// tracing render: with the camera's importance normalised over the whole film
// (Camera::importance), a light path's splats estimate pixel count x the pixel's value.
// Error estimate: a splatted pixel has no independent samples of its own, so its variance comes
// from the two half-images I_even and I_odd, independent estimates from n_even and n_odd paths:
// Var[I] is estimated by (I_even - I_odd)^2 n_even n_odd / n^2 (1 / 4 for equal halves), unbiased
// per pixel with one degree of freedom: noisy for one pixel, good averaged over an image.
// Extra layers (for bidirectional path tracing's per-strategy images) are plain sums, normalised
// in the same way, without error estimates.
class SplatFilm {
public:
    SplatFilm(int width, int height, int extra_layers = 0);

    int width() const { return width_; }
    int height() const { return height_; }

    // Adds a buffer's splats in their order, and counts its light paths. Not synchronised: called
    // by one thread, in work-unit order. An invalid splat (NaN, Inf, negative) is counted and
    // enters as zero, as Film::add_sample does with invalid samples.
    void add(const SplatBuffer& buffer);

    std::uint64_t light_paths() const { return paths_[0] + paths_[1]; }
    // Light paths per pixel: the "samples per pixel" of a splatted image.
    double light_paths_per_pixel() const;
    std::uint64_t invalid_splat_count() const { return invalid_splats_; }

    // The image: sum of splats / light paths per pixel.
    Image mean() const;
    // Extra layer `layer` (1 ... extra_layers), normalised as mean().
    Image layer_mean(int layer) const;
    int extra_layers() const { return static_cast<int>(layer_sums_.size()); }
    // The per-pixel variance of mean(), from the half-buffers (empty-black before both have paths).
    Image variance_of_mean() const;
    // Estimated relMSE of mean(), as Film::estimated_relative_mse but from variance_of_mean();
    // negative when not estimable.
    double estimated_relative_mse() const;
    // A Film holding mean() and variance_of_mean() with `samples_per_pixel` samples in every
    // pixel, for what takes a Film: checkpoints, merge (means weighted by sample counts), compare.
    Film to_film(std::uint64_t samples_per_pixel) const;

private:
    // The half-image of half h at pixel i, channel c: sum_h x pixel count / n_h.
    double half_image(int h, std::size_t i, int c) const;

    int width_, height_;
    std::vector<double> sums_[2];  // per half, per pixel, 3 channels
    std::vector<std::vector<double>> layer_sums_;  // per extra layer, per pixel, 3 channels
    std::uint64_t paths_[2] = {0, 0};
    std::uint64_t invalid_splats_ = 0;
};
// END BOOK

}  // namespace freezeray::ch04
