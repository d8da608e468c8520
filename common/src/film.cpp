// The film: per-pixel running mean and variance.
#include "freezeray/film.hpp"

#include "freezeray/metrics.hpp"

namespace freezeray {

Film::Film(int width, int height)
    : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * height) {}

void Film::add_sample(int x, int y, const Spectrum& radiance) {
    Spectrum value = radiance;
    if (!is_valid_radiance(value)) {
        invalid_samples_.fetch_add(1, std::memory_order_relaxed);
        value = Spectrum(0.0f);
    }
    Pixel& p = pixels_[index(x, y)];
    p.count += 1;
    const double n = static_cast<double>(p.count);
    for (int c = 0; c < 3; ++c) {
        // Welford's update: numerically stable for long renders, unlike sum and sum of squares.
        const double delta = value[c] - p.mean[c];
        p.mean[c] += delta / n;
        p.m2[c] += delta * (value[c] - p.mean[c]);
    }
}

std::uint64_t Film::total_sample_count() const {
    std::uint64_t total = 0;
    for (const Pixel& p : pixels_) total += p.count;
    return total;
}

Image Film::mean() const {
    Image image(width_, height_);
    for (std::size_t i = 0; i < pixels_.size(); ++i) {
        const Pixel& p = pixels_[i];
        image[i] = Spectrum(static_cast<float>(p.mean[0]), static_cast<float>(p.mean[1]), static_cast<float>(p.mean[2]));
    }
    return image;
}

Image Film::variance_of_mean() const {
    Image image(width_, height_);
    for (std::size_t i = 0; i < pixels_.size(); ++i) {
        const Pixel& p = pixels_[i];
        if (p.count < 2) continue;
        // Unbiased sample variance m2 / (n - 1), divided by n for the variance of the mean.
        const double scale = 1.0 / (static_cast<double>(p.count - 1) * static_cast<double>(p.count));
        image[i] = Spectrum(static_cast<float>(p.m2[0] * scale), static_cast<float>(p.m2[1] * scale),
                            static_cast<float>(p.m2[2] * scale));
    }
    return image;
}

double Film::estimated_relative_mse() const {
    double sum = 0.0;
    std::size_t counted = 0;
    for (const Pixel& p : pixels_) {
        if (p.count < 2) continue;
        const double scale = 1.0 / (static_cast<double>(p.count - 1) * static_cast<double>(p.count));
        for (int c = 0; c < 3; ++c) sum += p.m2[c] * scale / (p.mean[c] * p.mean[c] + RelativeMseEpsilon);
        counted += 3;
    }
    return counted > 0 ? sum / static_cast<double>(counted) : -1.0;
}

Film Film::from_images(const Image& mean, const Image& variance_of_mean, std::uint64_t samples) {
    Film film(mean.width(), mean.height());
    const double n = static_cast<double>(samples);
    for (std::size_t i = 0; i < film.pixels_.size(); ++i) {
        Pixel& p = film.pixels_[i];
        p.count = samples;
        for (int c = 0; c < 3; ++c) {
            p.mean[c] = mean[i][c];
            // Inverse of variance_of_mean(): m2 = Var[mean] * n * (n - 1).
            if (variance_of_mean.pixel_count() == film.pixels_.size() && samples > 1)
                p.m2[c] = static_cast<double>(variance_of_mean[i][c]) * n * (n - 1.0);
        }
    }
    return film;
}

}  // namespace freezeray
