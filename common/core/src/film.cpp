// The film: per-pixel running mean and variance.
#include "freezeray/film.hpp"

#include "freezeray/error.hpp"
#include "freezeray/metrics.hpp"

#include <algorithm>
#include <istream>
#include <ostream>

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

std::uint64_t Film::minimum_sample_count() const {
    std::uint64_t fewest = UINT64_MAX;
    for (const Pixel& p : pixels_) fewest = std::min(fewest, p.count);
    return pixels_.empty() ? 0 : fewest;
}

Film Film::clone() const {
    Film copy(width_, height_);
    copy.pixels_ = pixels_;
    copy.invalid_samples_ = invalid_samples_.load();
    return copy;
}

namespace {

// The state file starts with this tag and a format version.
constexpr char StateTag[8] = {'F', 'R', 'F', 'I', 'L', 'M', '0', '1'};

}  // namespace

void Film::write_state(std::ostream& out) const {
    out.write(StateTag, sizeof StateTag);
    const std::int32_t size[2] = {width_, height_};
    out.write(reinterpret_cast<const char*>(size), sizeof size);
    const std::uint64_t invalid = invalid_samples_.load();
    out.write(reinterpret_cast<const char*>(&invalid), sizeof invalid);
    out.write(reinterpret_cast<const char*>(pixels_.data()),
              static_cast<std::streamsize>(pixels_.size() * sizeof(Pixel)));
}

Film Film::read_state(std::istream& in, const std::string& where) {
    char tag[sizeof StateTag];
    std::int32_t size[2] = {0, 0};
    std::uint64_t invalid = 0;
    in.read(tag, sizeof tag);
    if (!in || !std::equal(tag, tag + sizeof tag, StateTag)) throw InputError(where, "is not a FreezeRay render state");
    in.read(reinterpret_cast<char*>(size), sizeof size);
    in.read(reinterpret_cast<char*>(&invalid), sizeof invalid);
    if (!in || size[0] < 1 || size[1] < 1 || static_cast<long long>(size[0]) * size[1] > (1LL << 26))
        throw InputError(where, "has an invalid image size");
    Film film(size[0], size[1]);
    in.read(reinterpret_cast<char*>(film.pixels_.data()), static_cast<std::streamsize>(film.pixels_.size() * sizeof(Pixel)));
    if (!in) throw InputError(where, "is truncated");
    film.invalid_samples_ = invalid;
    return film;
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

Film merge_films(const Film& a, const Film& b) {
    if (a.width() != b.width() || a.height() != b.height())
        throw InputError("merge", "the renders differ in size: " + std::to_string(a.width()) + "x" +
                                      std::to_string(a.height()) + " and " + std::to_string(b.width()) + "x" +
                                      std::to_string(b.height()));
    Film merged = a.clone();
    for (std::size_t i = 0; i < merged.pixels_.size(); ++i) {
        Film::Pixel& p = merged.pixels_[i];
        const Film::Pixel& q = b.pixels_[i];
        const double n = static_cast<double>(p.count) + static_cast<double>(q.count);
        if (n == 0.0) continue;
        for (int c = 0; c < 3; ++c) {
            const double delta = q.mean[c] - p.mean[c];
            p.m2[c] += q.m2[c] + delta * delta * static_cast<double>(p.count) * static_cast<double>(q.count) / n;
            p.mean[c] += delta * static_cast<double>(q.count) / n;
        }
        p.count += q.count;
    }
    merged.invalid_samples_ += b.invalid_samples_.load();
    return merged;
}

Film samples_added(const Film& total, const Film& earlier) {
    if (total.width() != earlier.width() || total.height() != earlier.height())
        throw InputError("samples_added", "the films differ in size: " + std::to_string(total.width()) + "x" +
                                              std::to_string(total.height()) + " and " + std::to_string(earlier.width()) +
                                              "x" + std::to_string(earlier.height()));
    Film added(total.width(), total.height());
    for (std::size_t i = 0; i < added.pixels_.size(); ++i) {
        const Film::Pixel& t = total.pixels_[i];
        const Film::Pixel& e = earlier.pixels_[i];
        if (e.count > t.count)
            throw InputError("samples_added", "pixel " + std::to_string(i) + " has " + std::to_string(e.count) +
                                                  " samples in the earlier film but " + std::to_string(t.count) + " in the later");
        Film::Pixel& a = added.pixels_[i];
        a.count = t.count - e.count;
        if (a.count == 0) continue;
        const double n = static_cast<double>(t.count), n_earlier = static_cast<double>(e.count);
        const double n_added = static_cast<double>(a.count);
        for (int c = 0; c < 3; ++c) {
            // merge_films solved for the added part: n mean = n_e mean_e + n_a mean_a, and
            // m2 = m2_e + m2_a + delta^2 n_e n_a / n with delta = mean_a - mean_e.
            a.mean[c] = (n * t.mean[c] - n_earlier * e.mean[c]) / n_added;
            const double delta = a.mean[c] - e.mean[c];
            // The difference of two rounded sums: a few ulps below zero where the added samples
            // are all equal, which is zero.
            a.m2[c] = std::max(0.0, t.m2[c] - e.m2[c] - delta * delta * n_earlier * n_added / n);
        }
    }
    added.invalid_samples_ = total.invalid_samples_.load() - std::min(total.invalid_samples_.load(), earlier.invalid_samples_.load());
    return added;
}

}  // namespace freezeray
