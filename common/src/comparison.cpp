// Fits, times to accuracy and crop regions for comparisons of integrators.
#include "freezeray/comparison.hpp"

#include "freezeray/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace freezeray {

namespace {

// The relMSE a checkpoint contributes to fits: measured when there is a reference.
double checkpoint_error(const Checkpoint& c) { return c.relative_mse >= 0.0 ? c.relative_mse : c.estimated_relative_mse; }

}  // namespace

Line fit_line(const std::vector<double>& x, const std::vector<double>& y) {
    const std::size_t count = std::min(x.size(), y.size());
    if (count < 2) return {};
    const double n = static_cast<double>(count);
    double mean_x = 0, mean_y = 0;
    for (std::size_t i = 0; i < count; ++i) {
        mean_x += x[i] / n;
        mean_y += y[i] / n;
    }
    double sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < count; ++i) {
        sxx += (x[i] - mean_x) * (x[i] - mean_x);
        sxy += (x[i] - mean_x) * (y[i] - mean_y);
    }
    if (sxx <= 0.0) return {};
    return {sxy / sxx, mean_y - (sxy / sxx) * mean_x};
}

double ConvergenceFit::predict(double seconds) const {
    return std::pow(10.0, intercept + slope * std::log10(seconds));
}

double ConvergenceFit::time_to_reach(double relative_mse) const {
    if (points == 0 || slope >= 0.0) return std::numeric_limits<double>::infinity();
    return std::pow(10.0, (std::log10(relative_mse) - intercept) / slope);
}

// BOOK(fit-convergence)
ConvergenceFit fit_convergence(const std::vector<Checkpoint>& checkpoints) {
    // Least squares on (log10 t, log10 relMSE). The first checkpoint (one sample per pixel) is
    // left out: its time is mostly start-up (threads, caches), not the estimator's cost.
    std::vector<double> xs, ys;
    for (std::size_t i = 1; i < checkpoints.size(); ++i) {
        const double error = checkpoint_error(checkpoints[i]);
        if (error > 0.0 && checkpoints[i].seconds > 0.0) {
            xs.push_back(std::log10(checkpoints[i].seconds));
            ys.push_back(std::log10(error));
        }
    }
    ConvergenceFit fit;
    if (xs.size() < 2) return fit;
    const Line line = fit_line(xs, ys);
    fit.slope = line.slope;
    fit.intercept = line.intercept;
    fit.points = static_cast<int>(xs.size());
    return fit;
}
// END BOOK

std::vector<TimeToAccuracy> times_to_accuracy(const std::vector<Checkpoint>& checkpoints, const ConvergenceFit& fit,
                                              const std::vector<double>& targets) {
    std::vector<TimeToAccuracy> result;
    for (double target : targets) {
        TimeToAccuracy t;
        t.target = target;
        t.seconds = fit.time_to_reach(target);
        // Measured: the first checkpoint at or below the target, interpolated log-linearly from
        // the one before it.
        for (std::size_t i = 0; i < checkpoints.size(); ++i) {
            const double error = checkpoint_error(checkpoints[i]);
            if (error > 0.0 && error <= target) {
                t.measured = true;
                t.seconds = checkpoints[i].seconds;
                if (i > 0) {
                    const double e0 = checkpoint_error(checkpoints[i - 1]);
                    const double t0 = checkpoints[i - 1].seconds;
                    if (e0 > target && t0 > 0.0 && e0 > error) {
                        const double s = (std::log10(e0) - std::log10(target)) / (std::log10(e0) - std::log10(error));
                        t.seconds = std::pow(10.0, std::log10(t0) + s * (std::log10(checkpoints[i].seconds) - std::log10(t0)));
                    }
                }
                break;
            }
        }
        result.push_back(t);
    }
    return result;
}

std::vector<CropRegion> highest_error_regions(const std::vector<IntegratorRun>& runs, const Image& reference,
                                              int size, int count) {
    const int width = reference.width(), height = reference.height();
    size = std::min({size, width, height});
    if (size <= 0) return {};
    // Per-pixel relative error averaged over the runs, then summed over every candidate square
    // (on a grid of half the square's side).
    std::vector<double> error(static_cast<std::size_t>(width) * height, 0.0);
    for (const IntegratorRun& run : runs) {
        if (run.result.image.width() != width || run.result.image.height() != height) continue;
        for (std::size_t i = 0; i < error.size(); ++i)
            for (int c = 0; c < 3; ++c)
                error[i] += std::abs(run.result.image[i][c] - reference[i][c]) / (std::abs(reference[i][c]) + RelativeMseEpsilon);
    }
    struct Candidate {
        double error;
        int x, y;
    };
    std::vector<Candidate> candidates;
    const int step = std::max(1, size / 2);
    for (int y = 0; y + size <= height; y += step)
        for (int x = 0; x + size <= width; x += step) {
            double sum = 0.0;
            for (int j = y; j < y + size; ++j)
                for (int i = x; i < x + size; ++i) sum += error[static_cast<std::size_t>(j) * width + i];
            candidates.push_back({sum, x, y});
        }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.error > b.error; });
    std::vector<CropRegion> regions;
    for (const Candidate& c : candidates) {
        if (static_cast<int>(regions.size()) >= count) break;
        const bool overlaps = std::any_of(regions.begin(), regions.end(), [&](const CropRegion& r) {
            return c.x < r.x + r.width && r.x < c.x + size && c.y < r.y + r.height && r.y < c.y + size;
        });
        if (!overlaps) regions.push_back({c.x, c.y, size, size, "highest error"});
    }
    return regions;
}

}  // namespace freezeray
