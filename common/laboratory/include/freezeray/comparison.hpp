// Comparing integrators on one scene: what each one's accuracy costs in time. The `compare`
// command fills a Comparison (renders, checkpoints, metrics, fits) and writes it as a report.
#pragma once

#include "freezeray/agreement.hpp"
#include "freezeray/image.hpp"
#include "freezeray/integrator.hpp"
#include "freezeray/run_plan.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace freezeray {

// The error of one render at one moment of its run (a pass boundary: 1, 2, 4, ... spp).
struct Checkpoint {
    double seconds = 0.0;                  // render time so far, excluding the time spent measuring
    std::uint64_t samples_per_pixel = 0;
    double mse = -1.0;                     // against the reference; negative without one
    double relative_mse = -1.0;            // against the reference, its noise included; negative without one
    double estimated_relative_mse = -1.0;  // from the film's per-pixel variance (no reference)
    // The same for the pass that ended here alone: the samples added since the previous
    // checkpoint (samples_added), its own time and errors. Cumulative images share their samples,
    // so their errors are correlated; the passes' are independent, which is what a fit's
    // confidence interval assumes. Negative when unknown (the first checkpoint has no pass before it).
    double pass_seconds = -1.0;
    std::uint64_t pass_samples_per_pixel = 0;
    double pass_relative_mse = -1.0;            // against the reference, its noise included
    double pass_estimated_relative_mse = -1.0;  // from the pass's own per-pixel variance
};

// A reference is itself a render with noise of its own. For a run x and a reference r whose
// noises are independent, E[(x - r)^2] = E[(x - mu)^2] + Var r: the relMSE measured against r is
// the run's own plus about the reference's own estimated relMSE, which is therefore subtracted.
// What is left is trusted only down to ReferenceMargin times the reference's own relMSE.
inline constexpr double ReferenceMargin = 10.0;

// The run's relMSE from one measured against the reference: less the reference's own relMSE
// (when known, i.e. >= 0).
double less_reference_noise(double measured_relative_mse, double reference_relative_mse);
// The smallest relMSE the reference can measure: ReferenceMargin times its own (0 when unknown).
double reference_floor(double reference_relative_mse);
// The relMSE of a checkpoint as fits and plots read it: measured when there is a reference (less
// the reference's own; negative, i.e. none, below the reference's floor), else estimated.
double checkpoint_error(const Checkpoint& checkpoint, double reference_relative_mse);
// The same for the checkpoint's pass alone (negative when its pass is unknown).
double pass_error(const Checkpoint& checkpoint, double reference_relative_mse);

// The line log10(relMSE) = intercept + slope log10(seconds) a run follows, fitted robustly: the
// Theil-Sen estimator (Theil 1950; Sen 1968), whose slope is the median of the slopes between
// every pair of points, so that one firefly moves it little, with Sen's 95% confidence interval.
// The points are the passes' own errors against their own durations (independent, so the
// interval holds); from cumulative checkpoints alone, which share their samples, the slope is
// given without an interval. An unbiased Monte Carlo estimator has slope -1 once the per-sample
// cost is steady; a fit whose interval excludes -1 signals fireflies still being found, bias, or
// a reference that is itself not converged.
struct ConvergenceFit {
    static constexpr int MinimumPoints = 4;          // points a fit needs
    static constexpr int MinimumPointsForInterval = 6;  // and its 95 % interval (fewer: too wide to say anything)
    static constexpr double MinimumTimeSpan = 4.0;   // and the ratio of their longest to shortest time

    double slope = 0.0;
    double intercept = 0.0;               // log10(relMSE) at 1 second
    double slope_low = 0.0, slope_high = 0.0;  // the slope's 95% confidence interval (from_passes)
    int points = 0;                       // points used (0: no fit)
    bool from_passes = false;             // fitted to the passes' own errors, with an interval
    std::string no_fit_reason;            // why there is no fit, when points == 0
    // The relMSE the fitted line predicts after `seconds`.
    double predict(double seconds) const;
    // Whether the slope has a confidence interval (see from_passes).
    bool has_interval() const { return points >= MinimumPointsForInterval && from_passes; }
    // Whether -1, the unbiased rate, lies within the slope's confidence interval.
    bool agrees_with_unbiased_rate() const { return has_interval() && slope_low <= -1.0 && -1.0 <= slope_high; }
    // Whether the interval excludes -1 (false when there is no interval).
    bool disagrees_with_unbiased_rate() const { return has_interval() && !agrees_with_unbiased_rate(); }
};

// When a run reaches a target relMSE: measured (interpolated between checkpoints) when it got
// there; else read forward from where the run ended (its last checkpoint) along the run's fitted
// slope (along -1, the rate of an unbiased estimator, when there is no fit), and shown as a number
// only within ExtrapolationLimit times the run's time. An error that does not fall is not read.
struct TimeToAccuracy {
    static constexpr double ExtrapolationLimit = 10.0;

    double target = 0.0;
    double seconds = 0.0;          // infinite when there is nothing to read forward (no error, or none falling)
    double slope = -1.0;           // the slope read along when not measured
    bool measured = false;
    bool beyond_limit = false;     // extrapolated beyond ExtrapolationLimit x the run's time
    bool below_reference_floor = false;  // a target the reference is too noisy to measure
};

struct IntegratorRun {
    std::string integrator;
    RenderResult result;                 // final image, variance, samples, time
    std::vector<Checkpoint> checkpoints; // in time order
    // Final metrics against the reference (negative without a reference). relative_mse is less the
    // reference's own (less_reference_noise), raw_relative_mse as measured.
    double mse = -1.0;
    double relative_mse = -1.0;
    double raw_relative_mse = -1.0;
    double ssim = -1.0;
    double mape = -1.0;
    double efficiency = -1.0;            // 1 / (relMSE x seconds), relMSE measured or estimated
    bool error_is_estimated = false;     // true when relMSE comes from the variance (no reference)
    ConvergenceFit fit;
    std::vector<TimeToAccuracy> time_to_accuracy;  // for 1e-2 and 1e-3
};

// A rectangle of the image shown magnified in the report.
struct CropRegion {
    int x = 0, y = 0, width = 0, height = 0;
    std::string reason;  // "highest error", "chosen by the user"
};

struct Comparison {
    std::string scene;                   // the scene file
    std::string renderer;                // program name (ch03, freezeray)
    std::string budget;                  // "equal time: 10 s each" or "equal samples: 64 spp each"
    bool equal_time = false;             // the budget is time (then time is not a result to rank)
    std::optional<Image> reference;      // absent: errors are estimated from the variance
    std::string reference_description;   // file and its sample count, when known
    double reference_relative_mse = -1.0;  // the reference's own estimated relMSE (its header); negative: unknown
    std::vector<IntegratorRun> runs;
    std::vector<CropRegion> crops;
    std::vector<RunAgreement> agreements;  // every pair of runs that both have variances
};

class Registry;

// What `compare` is asked to do (plain data, parsed in cli.cpp).
struct CompareRequest {
    std::string scene;
    std::vector<std::string> integrators;  // run names (RunName): an integrator, @ a sampler, @ a light sampler
    // The command line's selectors: the scene's kinds (--accel, --texture-layout) and the runs'
    // (--sampler, --light-sampler) where a run names none of its own.
    Selections selections;
    OptionValues options;                  // the chapters' options, given to every run's integrator
    double time_seconds = 0.0;           // > 0: equal time
    std::uint64_t samples_per_pixel = 0; // > 0: equal samples (when no time is given)
    std::string reference;               // optional reference image
    std::string out_folder;
    int threads = 0;
    std::uint64_t seed = 0;
    int max_depth = 0;
    int width = 0, height = 0;           // 0: the scene's
    std::vector<CropRegion> crops;       // user-chosen; highest-error ones are added
    bool quiet = false;
};

// The seed of a reference made for a comparison whose runs use `comparison_seed` (compare
// --make-reference): never comparison_seed itself, so that the reference's noise is independent of
// the runs' and errors against it are not too small.
std::uint64_t reference_seed(std::uint64_t comparison_seed);

// Checks the request (scene, integrator names, reference size, output folder) before any
// rendering, then renders the scene with each integrator and measures it. Throws InputError
// for bad input; nothing is written.
Comparison run_comparison(const CompareRequest& request, const Registry& registry);

// The least-squares line y = intercept + slope x through the points (x_i, y_i); slope and
// intercept are 0 when fewer than two distinct x are given.
struct Line {
    double slope = 0.0;
    double intercept = 0.0;
};
Line fit_line(const std::vector<double>& x, const std::vector<double>& y);

// Fits the passes' own errors when at least MinimumPoints of them (with an error > 0) span
// MinimumTimeSpan in time; else the cumulative checkpoints' (skipping the very first pass, whose
// time is dominated by start-up), without an interval; else no fit, with the reason.
// Measured errors are taken less the reference's own relMSE (when >= 0), and those below its
// floor are left out.
ConvergenceFit fit_convergence(const std::vector<Checkpoint>& checkpoints, double reference_relative_mse = -1.0);

// Time to reach each target relMSE (see TimeToAccuracy); the run's time is its last checkpoint's.
// Errors as for fit_convergence; a target below the reference's floor is not read at all.
std::vector<TimeToAccuracy> times_to_accuracy(const std::vector<Checkpoint>& checkpoints,
                                              const std::vector<double>& targets, double reference_relative_mse = -1.0);


// Every pair of runs (in index order) whose images have variances to compare with.
std::vector<RunAgreement> pairwise_agreements(const std::vector<IntegratorRun>& runs);


// The `count` square regions of side `size` where the renders' mean relative error against
// the reference is highest, not overlapping.
std::vector<CropRegion> highest_error_regions(const std::vector<IntegratorRun>& runs, const Image& reference,
                                              int size, int count);

// Writes report.md, report.html (self-contained: images embedded), convergence.csv and the
// images into `folder`. See common/laboratory/src/report_*.cpp.
void write_comparison_report(const Comparison& comparison, const std::string& folder);

}  // namespace freezeray
