// The splatting film: ordered splat buffers and half-buffer error estimates.
#include "freezeray/ch04/splat_film.hpp"

#include "freezeray/metrics.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch04 {

void SplatBuffer::add_splat(const Vec2& raster_position, const Spectrum& value, int layer) {
    const float x = std::floor(raster_position.x), y = std::floor(raster_position.y);
    if (!(x >= 0.0f && y >= 0.0f && x < static_cast<float>(width_) && y < static_cast<float>(height_))) return;
    const auto pixel = static_cast<std::uint32_t>(static_cast<int>(y) * width_ + static_cast<int>(x));
    splats_.push_back({pixel, half_, static_cast<std::uint16_t>(layer), value});
}

void SplatBuffer::clear() {
    splats_.clear();  // keeps its capacity: no allocation once the buffers have grown
    paths_[0] = paths_[1] = 0;
}

SplatFilm::SplatFilm(int width, int height, int extra_layers) : width_(width), height_(height) {
    const std::size_t values = static_cast<std::size_t>(width) * height * 3;
    sums_[0].assign(values, 0.0);
    sums_[1].assign(values, 0.0);
    layer_sums_.assign(static_cast<std::size_t>(std::max(extra_layers, 0)), std::vector<double>(values, 0.0));
}

void SplatFilm::add(const SplatBuffer& buffer) {
    for (const SplatBuffer::Splat& splat : buffer.splats()) {
        if (splat.layer > 0) {  // an extra image: its splats are copies of ones counted in layer 0
            if (splat.layer <= layer_sums_.size() && is_valid_radiance(splat.value)) {
                double* sum = &layer_sums_[splat.layer - 1u][static_cast<std::size_t>(splat.pixel) * 3];
                for (int c = 0; c < 3; ++c) sum[c] += splat.value[c];
            }
            continue;
        }
        if (!is_valid_radiance(splat.value)) {
            ++invalid_splats_;
            continue;
        }
        double* sum = &sums_[splat.half][static_cast<std::size_t>(splat.pixel) * 3];
        for (int c = 0; c < 3; ++c) sum[c] += splat.value[c];
    }
    paths_[0] += buffer.light_paths(0);
    paths_[1] += buffer.light_paths(1);
}

double SplatFilm::light_paths_per_pixel() const {
    return static_cast<double>(light_paths()) / (static_cast<double>(width_) * height_);
}

double SplatFilm::half_image(int h, std::size_t i, int c) const {
    return sums_[h][i * 3 + c] * (static_cast<double>(width_) * height_) / static_cast<double>(paths_[h]);
}

Image SplatFilm::mean() const {
    Image image(width_, height_);
    if (light_paths() == 0) return image;
    const double scale = 1.0 / light_paths_per_pixel();
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c)
            image[i][c] = static_cast<float>((sums_[0][i * 3 + c] + sums_[1][i * 3 + c]) * scale);
    return image;
}

Image SplatFilm::layer_mean(int layer) const {
    Image image(width_, height_);
    if (light_paths() == 0 || layer < 1 || layer > extra_layers()) return image;
    const double scale = 1.0 / light_paths_per_pixel();
    const std::vector<double>& sums = layer_sums_[static_cast<std::size_t>(layer - 1)];
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) image[i][c] = static_cast<float>(sums[i * 3 + c] * scale);
    return image;
}

Image SplatFilm::variance_of_mean() const {
    Image image(width_, height_);
    if (paths_[0] == 0 || paths_[1] == 0) return image;
    const double n = static_cast<double>(light_paths());
    // E[(I_even - I_odd)^2] = Var[I_even] + Var[I_odd] = v P^2 (1/n_even + 1/n_odd) for a
    // per-path variance v and P pixels, while Var[I] = v P^2 / n.
    const double scale = static_cast<double>(paths_[0]) * static_cast<double>(paths_[1]) / (n * n);
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double difference = half_image(0, i, c) - half_image(1, i, c);
            image[i][c] = static_cast<float>(difference * difference * scale);
        }
    return image;
}

double SplatFilm::estimated_relative_mse() const {
    if (paths_[0] == 0 || paths_[1] == 0) return -1.0;
    const Image image = mean();
    const Image variance = variance_of_mean();
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double m = image[i][c];
            sum += variance[i][c] / (m * m + RelativeMseEpsilon);
        }
    return sum / static_cast<double>(image.pixel_count() * 3);
}

Film SplatFilm::to_film(std::uint64_t samples_per_pixel) const {
    return Film::from_images(mean(), variance_of_mean(), samples_per_pixel);
}

}  // namespace freezeray::ch04
