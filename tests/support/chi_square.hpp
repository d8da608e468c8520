// The chi-square goodness-of-fit harness: does a sampling routine produce samples distributed as
// its own pdf says? Samples are binned into a histogram of equal-area cells, the pdf is integrated
// over each cell to get the expected counts, and Pearson's statistic is compared with the
// chi-square distribution. The method follows Mitsuba's chi2 test (Jakob, src/libcore/chisquare.cpp,
// 2011, and mitsuba3 python/mitsuba/chi2.py) and Nori's warptest (Jakob, 2014).
#pragma once

#include "statistics.hpp"

#include "freezeray/math.hpp"
#include "freezeray/random.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace freezeray::stats {

// Where the samples live, and how it is cut into cells. Every domain is a rectangle of two
// parameters (x, y) on which area is the domain's own measure, so cells of equal parameter area
// have equal measure:
//   sphere      x = phi in [0, 2 pi), y = cos(theta) in [-1, 1]  (d omega = d phi d cos(theta))
//   hemisphere  x = phi in [0, 2 pi), y = cos(theta) in [0, 1], around +z
//   unit square x, y in [0, 1), the point's own x and y
//   interval    x in [start, end], the point's x (y and z are ignored)
struct Domain {
    enum class Kind { Sphere, Hemisphere, UnitSquare, Interval };
    Kind kind = Kind::Sphere;
    double interval_start = 0.0;
    double interval_end = 1.0;

    static Domain sphere() { return {Kind::Sphere, 0.0, 1.0}; }
    static Domain hemisphere() { return {Kind::Hemisphere, 0.0, 1.0}; }
    static Domain unit_square() { return {Kind::UnitSquare, 0.0, 1.0}; }
    static Domain interval(double start, double end) { return {Kind::Interval, start, end}; }

    std::string name() const;
};

// Draws one sample (a unit direction, or a point whose unused coordinates are ignored), or nothing
// when the routine fails (a BSDF sample below the horizon, say).
using SampleFunction = std::function<std::optional<Vec3>(PCG32& random)>;

// The density of a sample with respect to the domain's measure (solid angle, area, length), per
// call of the sample function: if sampling fails with probability q, it integrates to 1 - q.
using DensityFunction = std::function<double(const Vec3& sample)>;

struct ChiSquareOptions {
    std::uint64_t sample_count = 1'000'000;
    // Cells: sphere and hemisphere resolution cos(theta) bands x 2 resolution phi sectors;
    // unit square resolution x resolution; interval resolution cells.
    int resolution = 10;
    double alpha = chi_square_test_alpha;  // the test's false-failure rate (STATISTICS.md)
    std::uint64_t seed = 1;
    // Cells expecting fewer samples are pooled into one (the chi-square approximation needs about 5).
    double minimum_expected_count = 5.0;
    // The pdf's integral over the domain must be this within integral_tolerance (relative); no
    // check when empty. It is also the sampler's success probability: the samples that return
    // nothing are compared with N (1 - this), or with N (1 - the pdf's integral) when empty.
    std::optional<double> expected_pdf_integral = 1.0;
    double integral_tolerance = 1e-3;
};

struct ChiSquareResult {
    bool passed = false;
    double statistic = 0.0;
    int degrees_of_freedom = 0;
    double p_value = 0.0;
    double pdf_integral = 0.0;  // the pdf integrated numerically over the domain

    std::uint64_t sample_count = 0;
    std::uint64_t samples_without_result = 0;  // the sample function returned nothing
    std::uint64_t samples_outside_domain = 0;  // NaN, not unit length, below the hemisphere, ...
    std::uint64_t samples_with_zero_pdf = 0;   // pdf(sample) is zero or not finite: a division by 0
    std::uint64_t samples_in_empty_cells = 0;  // landed in a cell the pdf gives no probability

    // The histogram: columns along x, rows along y (see Domain), row-major; plus the cell of samples
    // that did not come (observed samples_without_result, expected N (1 - pdf_integral)).
    Domain domain;
    int columns = 0;
    int rows = 0;
    std::vector<double> observed;
    std::vector<double> expected;
    double expected_without_result = 0.0;

    std::string message;  // the verdict and every reason for a failure, one per line
    // The observed and expected count of every cell, with its parameter ranges: for a failure report.
    std::string table() const;
};

// Pearson's statistic with low-count pooling, as in Mitsuba: visit cells by increasing expected
// count; cells below the minimum go into one pooled cell, and so do the next cells until the pool
// reaches the minimum. Returns the statistic and the number of cells used; samples observed in
// cells expecting none are added to samples_in_empty_cells. For discrete distributions (which
// light a sampler chooses) whose cells need no quadrature.
std::pair<double, int> pooled_statistic(const std::vector<double>& observed, const std::vector<double>& expected,
                                        double minimum_expected, std::uint64_t& samples_in_empty_cells);

// Runs the chi-square test of `sample` against `pdf` on `domain`. Fails when the p-value is at
// most options.alpha, when any sample is outside the domain or has zero pdf, or when the pdf's
// integral differs from options.expected_pdf_integral.
ChiSquareResult chi_square_test(const Domain& domain, const SampleFunction& sample, const DensityFunction& pdf,
                                const ChiSquareOptions& options = {});

// The integral of `function` over the domain (in its measure), by adaptive Simpson quadrature on
// the cells of the given resolution. For checks such as "eval * cos integrates to the albedo".
double integrate_over_domain(const Domain& domain, const DensityFunction& function, int resolution = 10);

}  // namespace freezeray::stats
