// Image error metrics on linear radiance. Sums are kept in double: a megapixel image has three
// million terms, and float would lose the small ones.
#include "freezeray/metrics.hpp"

#include "freezeray/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace freezeray {

namespace {

std::string size_text(const Image& image) { return std::to_string(image.width()) + "x" + std::to_string(image.height()); }

// Throws InputError unless the images have the same, non-zero size.
void check_comparable(const Image& image, const Image& reference) {
    check_same_size(image, reference, "image");
    if (reference.pixel_count() == 0) {
        throw InputError("image", "is empty (0x0): there is nothing to compare");
    }
}

// The mean of error(x, r) over all pixels and the three channels.
template <typename ChannelError>
double mean_over_channels(const Image& image, const Image& reference, ChannelError error) {
    check_comparable(image, reference);
    double sum = 0.0;
    for (std::size_t i = 0; i < reference.pixel_count(); ++i) {
        for (int c = 0; c < 3; ++c) {
            sum += error(static_cast<double>(image[i][c]), static_cast<double>(reference[i][c]));
        }
    }
    return sum / (3.0 * static_cast<double>(reference.pixel_count()));
}

// The luminance of every pixel, row by row.
std::vector<double> luminance_plane(const Image& image) {
    std::vector<double> plane;
    plane.reserve(image.pixel_count());
    for (const Spectrum& pixel : image.pixels()) plane.push_back(luminance(pixel));
    return plane;
}

// The first row (or column) of each SSIM window along an axis of `size` pixels: every
// `stride` pixels, plus one window flush with the far edge so that every pixel is covered.
std::vector<int> window_starts(int size, int window, int stride) {
    std::vector<int> starts;
    for (int start = 0; start + window <= size; start += stride) starts.push_back(start);
    if (starts.back() != size - window) starts.push_back(size - window);
    return starts;
}

}  // namespace

// Throws InputError(what, "is WxH but the reference is WxH") when the sizes differ.
void check_same_size(const Image& image, const Image& reference, const std::string& what) {
    if (image.width() != reference.width() || image.height() != reference.height()) {
        throw InputError(what, "is " + size_text(image) + " but the reference is " + size_text(reference));
    }
}

// Mean of (x - r)^2.
double mse(const Image& image, const Image& reference) {
    return mean_over_channels(image, reference, [](double x, double r) { return (x - r) * (x - r); });
}

// Mean of (x - r)^2 / (r^2 + epsilon) (Rousselle, Knaus and Zwicker 2011, see metrics.hpp).
double relative_mse(const Image& image, const Image& reference, double epsilon) {
    return mean_over_channels(image, reference,
                              [epsilon](double x, double r) { return (x - r) * (x - r) / (r * r + epsilon); });
}

// Square root of the MSE, in the units of the radiance.
double rmse(const Image& image, const Image& reference) { return std::sqrt(mse(image, reference)); }

// 10 log10(peak^2 / MSE) in decibels; +infinity for identical images.
double psnr(const Image& image, const Image& reference, double peak) {
    const double error = mse(image, reference);
    if (error == 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(peak * peak / error);
}

// Mean of |x - r| / (|r| + epsilon).
double mape(const Image& image, const Image& reference, double epsilon) {
    return mean_over_channels(image, reference,
                              [epsilon](double x, double r) { return std::abs(x - r) / (std::abs(r) + epsilon); });
}

// Mean SSIM over 8x8 windows of luminance, in [-1, 1], 1 for identical images.
//
// Wang, Bovik, Sheikh and Simoncelli, "Image Quality Assessment: From Error Visibility to
// Structural Similarity", IEEE Transactions on Image Processing 13(4), 2004. In each window,
//     SSIM = (2 mu_x mu_y + C1)(2 sigma_xy + C2) / ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2))
// (their eq. 13), with sample (co)variances normalised by N - 1 as in the paper, K1 = 0.01,
// K2 = 0.03, and the image's score is the mean over windows (their eq. 17).
//
// Our choices: square windows with uniform weights (the paper's 8x8 variant rather than its
// 11x11 Gaussian), placed every 4 pixels plus one flush with the right and bottom edges; a
// dimension smaller than 8 pixels gets a single window as wide as the image. The dynamic range
// L is the reference's peak luminance (renders are not bounded by 1), or 1 for a black reference.
double ssim(const Image& image, const Image& reference) {
    check_comparable(image, reference);
    const std::vector<double> x = luminance_plane(image);
    const std::vector<double> y = luminance_plane(reference);

    double peak = *std::max_element(y.begin(), y.end());
    if (!(peak > 0.0)) peak = 1.0;
    const double c1 = (0.01 * peak) * (0.01 * peak);
    const double c2 = (0.03 * peak) * (0.03 * peak);

    const int width = reference.width();
    const int window_width = std::min(8, width), window_height = std::min(8, reference.height());
    const double n = static_cast<double>(window_width * window_height);
    const double n_minus_1 = std::max(n - 1.0, 1.0);  // a 1x1 window has zero variance anyway

    double sum = 0.0;
    int windows = 0;
    for (int top : window_starts(reference.height(), window_height, 4)) {
        for (int left : window_starts(width, window_width, 4)) {
            // Two passes: the means first, then deviations from them (stable for bright images).
            double mean_x = 0.0, mean_y = 0.0;
            for (int j = top; j < top + window_height; ++j) {
                for (int i = left; i < left + window_width; ++i) {
                    mean_x += x[static_cast<std::size_t>(j) * width + i];
                    mean_y += y[static_cast<std::size_t>(j) * width + i];
                }
            }
            mean_x /= n;
            mean_y /= n;
            double variance_x = 0.0, variance_y = 0.0, covariance = 0.0;
            for (int j = top; j < top + window_height; ++j) {
                for (int i = left; i < left + window_width; ++i) {
                    const double dx = x[static_cast<std::size_t>(j) * width + i] - mean_x;
                    const double dy = y[static_cast<std::size_t>(j) * width + i] - mean_y;
                    variance_x += dx * dx;
                    variance_y += dy * dy;
                    covariance += dx * dy;
                }
            }
            variance_x /= n_minus_1;
            variance_y /= n_minus_1;
            covariance /= n_minus_1;
            sum += (2.0 * mean_x * mean_y + c1) * (2.0 * covariance + c2) /
                   ((mean_x * mean_x + mean_y * mean_y + c1) * (variance_x + variance_y + c2));
            ++windows;
        }
    }
    return sum / windows;
}

}  // namespace freezeray
