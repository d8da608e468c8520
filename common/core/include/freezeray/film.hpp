// The film: per-pixel running mean and variance of the samples, so that the error of an image
// can be estimated without a reference.
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/math.hpp"

#include <atomic>
#include <cstdint>
#include <iosfwd>
#include <vector>

namespace freezeray {

class Film {
public:
    Film(int width, int height);
    Film(Film&& other) noexcept
        : width_(other.width_), height_(other.height_), pixels_(std::move(other.pixels_)),
          invalid_samples_(other.invalid_samples_.load()) {}
    Film& operator=(Film&& other) noexcept {
        width_ = other.width_;
        height_ = other.height_;
        pixels_ = std::move(other.pixels_);
        invalid_samples_ = other.invalid_samples_.load();
        return *this;
    }

    int width() const { return width_; }
    int height() const { return height_; }

    // Adds one sample of pixel (x, y) with Welford's update (Welford 1962; Knuth, TAOCP vol. 2,
    // 4.2.2). Not synchronised: the tile loop gives each pixel to one thread at a time, in
    // sample order, which also makes the result independent of the thread count.
    // An invalid sample (NaN, Inf, negative) is counted and enters as zero: the estimator
    // stays defined and the count tells that something is wrong.
    void add_sample(int x, int y, const Spectrum& radiance);

    std::uint64_t sample_count(int x, int y) const { return pixels_[index(x, y)].count; }
    // The fewest samples any pixel has: the sample count every pixel has reached.
    std::uint64_t minimum_sample_count() const;
    std::uint64_t invalid_sample_count() const { return invalid_samples_.load(); }
    std::uint64_t total_sample_count() const;

    // The per-pixel mean: the image estimate.
    Image mean() const;
    // The per-pixel variance of the mean (sample variance / n): the expected squared error of
    // each pixel of mean(), for an unbiased estimator.
    Image variance_of_mean() const;

    // Estimated relMSE of mean() against the (unknown) exact image: the mean over pixels and
    // channels of Var[mean] / (mean^2 + epsilon). See metrics.hpp for epsilon.
    double estimated_relative_mse() const;

    // Restores a film from a mean and variance-of-mean image with a uniform sample count
    // (to resume a render, or merge renders). variance may be empty (zero variance).
    static Film from_images(const Image& mean, const Image& variance_of_mean, std::uint64_t samples);

    // An exact copy (the running sums in full precision), e.g. to continue a render.
    Film clone() const;

    // The exact state, for resuming a render bit for bit: width, height, and every pixel's
    // running mean, sum of squared deviations and count, in binary. read_state throws
    // InputError(`where`, ...) on a truncated or inconsistent stream.
    void write_state(std::ostream& out) const;
    static Film read_state(std::istream& in, const std::string& where);

    friend Film merge_films(const Film& a, const Film& b);
    friend Film samples_added(const Film& total, const Film& earlier);

private:
    struct Pixel {
        double mean[3] = {0, 0, 0};
        double m2[3] = {0, 0, 0};  // sum of squared deviations from the mean
        std::uint64_t count = 0;
    };
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width_ + x; }

    int width_, height_;
    std::vector<Pixel> pixels_;
    std::atomic<std::uint64_t> invalid_samples_{0};
};

// Combines two films of the same image made from disjoint samples: per pixel, the means are
// weighted by their sample counts and the squared deviations combined exactly (Chan, Golub and
// LeVeque, "Updating Formulae and a Pairwise Algorithm for Computing Sample Variances", 1979).
Film merge_films(const Film& a, const Film& b);

// The inverse: the film of the samples `total` holds beyond those of `earlier`, a film of the same
// render taken at an earlier moment (per pixel, earlier's count at most total's). A comparison
// reads each pass's own samples this way: they are independent of the earlier passes', where
// the cumulative images that hold them are not. Throws InputError for films that differ in size
// or where `earlier` has more samples than `total`.
Film samples_added(const Film& total, const Film& earlier);

}  // namespace freezeray
