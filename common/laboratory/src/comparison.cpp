// Fits, times to accuracy and crop regions for comparisons of integrators.
#include "freezeray/comparison.hpp"

#include "freezeray/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace freezeray {

namespace {

// A relMSE as fits and plots read it: measured against the reference when there is one (less
// the reference's own, none below its floor), else estimated from the variance.
double read_error(double measured, double estimated, double reference_relative_mse) {
    if (measured < 0.0) return estimated;
    const double error = less_reference_noise(measured, reference_relative_mse);
    return error >= reference_floor(reference_relative_mse) && error > 0.0 ? error : -1.0;
}

}  // namespace

double checkpoint_error(const Checkpoint& c, double reference_relative_mse) {
    return read_error(c.relative_mse, c.estimated_relative_mse, reference_relative_mse);
}

double pass_error(const Checkpoint& c, double reference_relative_mse) {
    if (!(c.pass_seconds > 0.0)) return -1.0;
    return read_error(c.pass_relative_mse, c.pass_estimated_relative_mse, reference_relative_mse);
}

double less_reference_noise(double measured_relative_mse, double reference_relative_mse) {
    return reference_relative_mse > 0.0 ? measured_relative_mse - reference_relative_mse : measured_relative_mse;
}

double reference_floor(double reference_relative_mse) {
    return reference_relative_mse > 0.0 ? ReferenceMargin * reference_relative_mse : 0.0;
}

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

namespace {

// The points a run's fits read: (log10 seconds, log10 relMSE) of its checkpoints with an error,
// the first left out (one sample per pixel: its time is mostly start-up, threads and caches, not
// the estimator's cost).
struct LogPoints {
    std::vector<double> x, y;
};

LogPoints log_points(const std::vector<Checkpoint>& checkpoints, double reference_relative_mse) {
    LogPoints points;
    for (std::size_t i = 1; i < checkpoints.size(); ++i) {
        const double error = checkpoint_error(checkpoints[i], reference_relative_mse);
        if (error > 0.0 && checkpoints[i].seconds > 0.0 && std::isfinite(error)) {
            points.x.push_back(std::log10(checkpoints[i].seconds));
            points.y.push_back(std::log10(error));
        }
    }
    return points;
}

// The same for the passes alone: (log10 of a pass's own time, log10 of its own samples' relMSE).
// The first checkpoint has no pass before it; the pass from 1 to 2 spp is all render time.
LogPoints pass_log_points(const std::vector<Checkpoint>& checkpoints, double reference_relative_mse) {
    LogPoints points;
    for (const Checkpoint& c : checkpoints) {
        const double error = pass_error(c, reference_relative_mse);
        if (error > 0.0 && std::isfinite(error)) {
            points.x.push_back(std::log10(c.pass_seconds));
            points.y.push_back(std::log10(error));
        }
    }
    return points;
}

// Why a set of points cannot carry a fit, or empty when it can.
std::string unfit_reason(const LogPoints& p, const char* what) {
    const std::size_t n = p.x.size();
    if (n < static_cast<std::size_t>(ConvergenceFit::MinimumPoints))
        return std::to_string(n) + " " + what + (n == 1 ? "" : "s") + ", " +
               std::to_string(ConvergenceFit::MinimumPoints) + " needed";
    const auto [low, high] = std::minmax_element(p.x.begin(), p.x.end());
    const double span = std::pow(10.0, *high - *low);
    if (span < ConvergenceFit::MinimumTimeSpan) {
        char text[96];
        std::snprintf(text, sizeof text, "%ss span %.1fx in time, %.0fx needed", what, span, ConvergenceFit::MinimumTimeSpan);
        return text;
    }
    return {};
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

// BOOK(fit-convergence)
ConvergenceFit fit_convergence(const std::vector<Checkpoint>& checkpoints, double reference_relative_mse) {
    // The passes' own errors are independent of each other, so Sen's interval holds for them;
    // the cumulative checkpoints' are not (each image holds all the samples of the one before),
    // their points lie too smoothly on a line and an interval from them would be too narrow.
    // Both follow the same curve: the relMSE of a mean of M samples does not depend on which
    // M they are, so a pass of duration d has the error a whole render of duration d would have.
    ConvergenceFit fit;
    LogPoints p = pass_log_points(checkpoints, reference_relative_mse);
    fit.from_passes = unfit_reason(p, "pass").empty();
    if (!fit.from_passes) {
        p = log_points(checkpoints, reference_relative_mse);
        fit.no_fit_reason = unfit_reason(p, "checkpoint");
        if (!fit.no_fit_reason.empty()) return fit;
    }
    const std::size_t n = p.x.size();
    // Theil-Sen: the median of the slopes between every pair of points (at different times).
    std::vector<double> slopes;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (p.x[j] != p.x[i]) slopes.push_back((p.y[j] - p.y[i]) / (p.x[j] - p.x[i]));
    if (slopes.empty()) {
        fit.no_fit_reason = "every checkpoint at the same time";
        return fit;
    }
    std::sort(slopes.begin(), slopes.end());
    fit.slope = median(slopes);
    std::vector<double> intercepts(n);
    for (std::size_t i = 0; i < n; ++i) intercepts[i] = p.y[i] - fit.slope * p.x[i];
    fit.intercept = median(intercepts);
    fit.points = static_cast<int>(n);
    if (!fit.from_passes) return fit;  // no interval from correlated points
    // Sen's 95% interval: the slopes of ranks (N -+ C) / 2 among the N sorted ones, with
    // C = 1.96 sqrt(n (n - 1) (2n + 5) / 18), the normal approximation to Kendall's tau's spread
    // (Sen 1968; Hollander and Wolfe, "Nonparametric Statistical Methods", 1973, section 9.3).
    const double count = static_cast<double>(slopes.size()), nd = static_cast<double>(n);
    const double c = 1.96 * std::sqrt(nd * (nd - 1.0) * (2.0 * nd + 5.0) / 18.0);
    const auto at_rank = [&](double rank) {  // ranks from 1
        const double clamped = std::clamp(std::round(rank), 1.0, count);
        return slopes[static_cast<std::size_t>(clamped) - 1];
    };
    fit.slope_low = at_rank((count - c) / 2.0);
    fit.slope_high = at_rank((count + c) / 2.0 + 1.0);
    return fit;
}
// END BOOK

// BOOK(time-to-accuracy)
std::vector<TimeToAccuracy> times_to_accuracy(const std::vector<Checkpoint>& checkpoints,
                                              const std::vector<double>& targets, double reference_relative_mse) {
    // Where the run ended: its last checkpoint with an error. Beyond it the time is read along the
    // run's own fitted slope (the rate it was actually converging at), or along -1, the unbiased
    // rate, when there is no fit; an error that does not fall is never read forward.
    const ConvergenceFit fit = fit_convergence(checkpoints, reference_relative_mse);
    const double slope = fit.points > 0 ? fit.slope : -1.0;
    double end_seconds = 0.0, end_error = 0.0;
    for (const Checkpoint& c : checkpoints)
        if (const double error = checkpoint_error(c, reference_relative_mse); error > 0.0 && c.seconds > 0.0) {
            end_seconds = c.seconds;
            end_error = error;
        }
    const double run_seconds = checkpoints.empty() ? 0.0 : checkpoints.back().seconds;
    std::vector<TimeToAccuracy> result;
    for (double target : targets) {
        TimeToAccuracy t;
        t.target = target;
        if (target < reference_floor(reference_relative_mse)) {
            t.below_reference_floor = true;
            t.seconds = std::numeric_limits<double>::quiet_NaN();
            result.push_back(t);
            continue;
        }
        t.slope = slope;
        t.seconds = end_error > 0.0 && slope < 0.0
                        ? end_seconds * std::pow(target / end_error, 1.0 / slope)  // error ~ seconds^slope
                        : std::numeric_limits<double>::infinity();
        // Measured: the first checkpoint at or below the target, interpolated log-linearly from
        // the one before it.
        for (std::size_t i = 0; i < checkpoints.size(); ++i) {
            const double error = checkpoint_error(checkpoints[i], reference_relative_mse);
            if (error > 0.0 && error <= target) {
                t.measured = true;
                t.seconds = checkpoints[i].seconds;
                if (i > 0) {
                    const double e0 = checkpoint_error(checkpoints[i - 1], reference_relative_mse);
                    const double t0 = checkpoints[i - 1].seconds;
                    if (e0 > target && t0 > 0.0 && e0 > error) {
                        const double s = (std::log10(e0) - std::log10(target)) / (std::log10(e0) - std::log10(error));
                        t.seconds = std::pow(10.0, std::log10(t0) + s * (std::log10(checkpoints[i].seconds) - std::log10(t0)));
                    }
                }
                break;
            }
        }
        // Read beyond ExtrapolationLimit times the run's time, the line is a guess, not a figure.
        if (!t.measured) t.beyond_limit = !(t.seconds <= TimeToAccuracy::ExtrapolationLimit * run_seconds);
        result.push_back(t);
    }
    return result;
}
// END BOOK

std::vector<RunAgreement> pairwise_agreements(const std::vector<IntegratorRun>& runs) {
    std::vector<const RenderResult*> results;
    for (const IntegratorRun& run : runs) results.push_back(&run.result);
    return pairwise_agreements(results);
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
