// The chi-square goodness-of-fit harness. Pearson's statistic sum (O - E)^2 / E over histogram
// cells is asymptotically chi-square distributed with (cells - 1) degrees of freedom when every
// E is large enough (Pearson 1900; e.g. Cochran, "Some Methods for Strengthening the Common chi^2
// Tests", Biometrics 10, 1954, for the "about 5" rule). Cells are pooled as in Mitsuba's chi2 test.
#include "chi_square.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <numeric>
#include <sstream>

namespace freezeray::stats {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

// The parameter rectangle [x0, x1] x [y0, y1] of a domain, cut into columns x rows cells.
struct Grid {
    double x0, x1, y0, y1;
    int columns, rows;

    double cell_width() const { return (x1 - x0) / columns; }
    double cell_height() const { return (y1 - y0) / rows; }
};

Grid grid_for(const Domain& domain, int resolution) {
    const int r = std::max(resolution, 1);
    switch (domain.kind) {
        case Domain::Kind::Sphere: return {0.0, two_pi, -1.0, 1.0, 2 * r, r};
        case Domain::Kind::Hemisphere: return {0.0, two_pi, 0.0, 1.0, 2 * r, r};
        case Domain::Kind::UnitSquare: return {0.0, 1.0, 0.0, 1.0, r, r};
        case Domain::Kind::Interval: break;
    }
    return {domain.interval_start, domain.interval_end, 0.0, 1.0, r, 1};
}

// The point of the domain at parameters (x, y).
Vec3 point_at(const Domain& domain, double x, double y) {
    switch (domain.kind) {
        case Domain::Kind::Sphere:
        case Domain::Kind::Hemisphere: {
            const double sin_theta = std::sqrt(std::max(0.0, 1.0 - y * y));
            return Vec3(static_cast<float>(sin_theta * std::cos(x)), static_cast<float>(sin_theta * std::sin(x)),
                        static_cast<float>(y));
        }
        case Domain::Kind::UnitSquare: return Vec3(static_cast<float>(x), static_cast<float>(y), 0.0f);
        case Domain::Kind::Interval: break;
    }
    return Vec3(static_cast<float>(x), 0.0f, 0.0f);
}

// The cell a sample falls in, or nothing when the sample is not a point of the domain.
std::optional<int> cell_of(const Domain& domain, const Grid& grid, const Vec3& sample) {
    double x = 0.0;
    double y = 0.5;
    if (!std::isfinite(sample.x) || !std::isfinite(sample.y) || !std::isfinite(sample.z)) return std::nullopt;
    switch (domain.kind) {
        case Domain::Kind::Sphere:
        case Domain::Kind::Hemisphere: {
            const double length = std::sqrt(double(sample.x) * sample.x + double(sample.y) * sample.y +
                                            double(sample.z) * sample.z);
            if (std::abs(length - 1.0) > 1e-4) return std::nullopt;  // not a unit direction
            if (domain.kind == Domain::Kind::Hemisphere && sample.z < 0.0f) return std::nullopt;
            x = std::atan2(double(sample.y), double(sample.x));
            if (x < 0.0) x += two_pi;
            y = std::clamp(sample.z / length, -1.0, 1.0);
            break;
        }
        case Domain::Kind::UnitSquare:
            x = sample.x;
            y = sample.y;
            if (x < 0.0 || x > 1.0 || y < 0.0 || y > 1.0) return std::nullopt;
            break;
        case Domain::Kind::Interval:
            x = sample.x;
            if (x < grid.x0 || x > grid.x1) return std::nullopt;
            break;
    }
    const int column = std::clamp(static_cast<int>((x - grid.x0) / grid.cell_width()), 0, grid.columns - 1);
    const int row = std::clamp(static_cast<int>((y - grid.y0) / grid.cell_height()), 0, grid.rows - 1);
    return row * grid.columns + column;
}

// Adaptive Simpson quadrature (Lyness, "Notes on the Adaptive Simpson Quadrature Routine",
// J. ACM 16(3), 1969): an interval is halved until Simpson's rule on the halves agrees with the
// whole within 15 x tolerance, then Richardson's correction is added. The first levels are always
// split so that a feature narrower than the cell is not missed by the five first points.
constexpr int minimum_depth = 2;
constexpr int maximum_depth = 12;
constexpr double relative_tolerance = 1e-6;

template <typename Function>
double simpson_step(const Function& f, double a, double b, double fa, double fm, double fb, double whole,
                    double tolerance, int depth) {
    const double m = 0.5 * (a + b);
    const double left_middle = 0.5 * (a + m);
    const double right_middle = 0.5 * (m + b);
    const double f_left = f(left_middle);
    const double f_right = f(right_middle);
    const double left = (m - a) / 6.0 * (fa + 4.0 * f_left + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * f_right + fb);
    const double change = left + right - whole;
    if (depth >= maximum_depth || (depth >= minimum_depth && std::abs(change) <= 15.0 * tolerance))
        return left + right + change / 15.0;
    return simpson_step(f, a, m, fa, f_left, fm, left, 0.5 * tolerance, depth + 1) +
           simpson_step(f, m, b, fm, f_right, fb, right, 0.5 * tolerance, depth + 1);
}

template <typename Function>
double adaptive_simpson(const Function& f, double a, double b) {
    const double fa = f(a);
    const double fm = f(0.5 * (a + b));
    const double fb = f(b);
    const double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    const double tolerance = relative_tolerance * std::max(std::abs(whole), 1e-300);
    return simpson_step(f, a, b, fa, fm, fb, whole, tolerance, 0);
}

// The integral of f over every cell, in the domain's measure (the parameters have Jacobian 1).
std::vector<double> integrate_cells(const Domain& domain, const Grid& grid, const DensityFunction& f) {
    std::vector<double> integrals(static_cast<std::size_t>(grid.columns) * grid.rows);
    for (int row = 0; row < grid.rows; ++row) {
        for (int column = 0; column < grid.columns; ++column) {
            const double x0 = grid.x0 + column * grid.cell_width();
            const double x1 = column + 1 == grid.columns ? grid.x1 : x0 + grid.cell_width();
            const double y0 = grid.y0 + row * grid.cell_height();
            const double y1 = row + 1 == grid.rows ? grid.y1 : y0 + grid.cell_height();
            const auto along_x = [&](double y) {
                return adaptive_simpson([&](double x) { return f(point_at(domain, x, y)); }, x0, x1);
            };
            integrals[static_cast<std::size_t>(row) * grid.columns + column] =
                domain.kind == Domain::Kind::Interval ? along_x(0.5) : adaptive_simpson(along_x, y0, y1);
        }
    }
    return integrals;
}

std::string count_line(std::uint64_t count, std::uint64_t total, const std::string& what) {
    return std::to_string(count) + " of " + std::to_string(total) + " samples " + what + "\n";
}

}  // namespace

std::pair<double, int> pooled_statistic(const std::vector<double>& observed, const std::vector<double>& expected,
                                        double minimum_expected, std::uint64_t& samples_in_empty_cells) {
    std::vector<std::size_t> order(expected.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
    double statistic = 0.0;
    int cells = 0;
    double pooled_observed = 0.0;
    double pooled_expected = 0.0;
    for (std::size_t i : order) {
        if (expected[i] <= 0.0) {
            samples_in_empty_cells += static_cast<std::uint64_t>(observed[i]);
        } else if (expected[i] < minimum_expected || (pooled_expected > 0.0 && pooled_expected < minimum_expected)) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
        } else {
            statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
            ++cells;
        }
    }
    if (pooled_expected > 0.0) {
        statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
        ++cells;
    }
    return {statistic, cells};
}

std::string Domain::name() const {
    switch (kind) {
        case Kind::Sphere: return "sphere";
        case Kind::Hemisphere: return "hemisphere";
        case Kind::UnitSquare: return "unit square";
        case Kind::Interval: break;
    }
    return "interval [" + format_number(interval_start) + ", " + format_number(interval_end) + "]";
}

double integrate_over_domain(const Domain& domain, const DensityFunction& function, int resolution) {
    const std::vector<double> cells = integrate_cells(domain, grid_for(domain, resolution), function);
    return std::accumulate(cells.begin(), cells.end(), 0.0);
}

ChiSquareResult chi_square_test(const Domain& domain, const SampleFunction& sample, const DensityFunction& pdf,
                                const ChiSquareOptions& options) {
    const Grid grid = grid_for(domain, options.resolution);
    ChiSquareResult result;
    result.domain = domain;
    result.columns = grid.columns;
    result.rows = grid.rows;
    result.sample_count = options.sample_count;
    result.observed.assign(static_cast<std::size_t>(grid.columns) * grid.rows, 0.0);

    PCG32 random = make_chain_stream(options.seed, 0);
    for (std::uint64_t i = 0; i < options.sample_count; ++i) {
        const std::optional<Vec3> point = sample(random);
        if (!point) {
            ++result.samples_without_result;
            continue;
        }
        const std::optional<int> cell = cell_of(domain, grid, *point);
        if (!cell) {
            ++result.samples_outside_domain;
            continue;
        }
        const double density = pdf(*point);
        if (!(density > 0.0) || !std::isfinite(density)) ++result.samples_with_zero_pdf;
        result.observed[static_cast<std::size_t>(*cell)] += 1.0;
    }

    result.expected = integrate_cells(domain, grid, pdf);
    result.pdf_integral = std::accumulate(result.expected.begin(), result.expected.end(), 0.0);
    const double n = static_cast<double>(options.sample_count);
    for (double& e : result.expected) e *= n;
    // The samples that did not come expect N (1 - success probability): the probability the test
    // states (expected_pdf_integral, which the pdf's integral must match within its tolerance),
    // else the pdf's integral. The stated value keeps the quadrature's own error out of this
    // cell: where a pdf has edges across cells (an area light's outline) the integral can fall
    // short by 4e-5, and a sampler that never fails would be charged 40 missing failures in 1e6.
    const double success = options.expected_pdf_integral ? *options.expected_pdf_integral : result.pdf_integral;
    result.expected_without_result = std::max(0.0, n * (1.0 - success));

    // The histogram's cells plus the cell of samples that did not come: a multinomial over all
    // outcomes of a call to the sample function, so dof = cells used - 1.
    std::vector<double> observed = result.observed;
    std::vector<double> expected = result.expected;
    if (result.expected_without_result > 0.0) {
        observed.push_back(static_cast<double>(result.samples_without_result));
        expected.push_back(result.expected_without_result);
    }
    const auto [statistic, cells] =
        pooled_statistic(observed, expected, options.minimum_expected_count, result.samples_in_empty_cells);
    result.statistic = statistic;
    result.degrees_of_freedom = cells - 1;
    result.p_value = result.degrees_of_freedom >= 1 ? chi_square_survival(statistic, result.degrees_of_freedom) : 0.0;

    std::string problems;
    if (result.samples_outside_domain > 0)
        problems += count_line(result.samples_outside_domain, result.sample_count,
                               "are not points of the " + domain.name() + " (NaN, not unit length, or outside)");
    if (result.samples_with_zero_pdf > 0)
        problems += count_line(result.samples_with_zero_pdf, result.sample_count,
                               "have pdf(sample) zero or not finite (the sampler makes what the pdf calls impossible)");
    if (result.samples_without_result > 0 && result.expected_without_result <= 0.0)
        problems += count_line(result.samples_without_result, result.sample_count,
                               "returned nothing, yet the pdf integrates to 1 or more (a sampler that can fail "
                               "needs a pdf integrating to its probability of success)");
    if (result.samples_in_empty_cells > 0)
        problems += count_line(result.samples_in_empty_cells, result.sample_count,
                               "landed in cells where the pdf integrates to zero");
    if (result.degrees_of_freedom < 1)
        problems += "too few cells with enough expected samples (" + std::to_string(cells) +
                    "): raise sample_count or resolution\n";
    else if (!(result.p_value > options.alpha))
        problems += "the histogram does not match the pdf: chi^2 = " + format_number(statistic) + ", dof " +
                    std::to_string(result.degrees_of_freedom) + ", p = " + format_number(result.p_value) +
                    " <= alpha " + format_number(options.alpha) + "\n";
    if (options.expected_pdf_integral &&
        !(std::abs(result.pdf_integral - *options.expected_pdf_integral) <=
          options.integral_tolerance * std::abs(*options.expected_pdf_integral)))
        problems += "the pdf integrates to " + format_number(result.pdf_integral) + " over the " + domain.name() +
                    ", expected " + format_number(*options.expected_pdf_integral) + "\n";

    if (!problems.empty()) problems.pop_back();  // the last line's newline
    result.passed = problems.empty();
    result.message = std::string("chi-square test on the ") + domain.name() + ": chi^2 = " + format_number(statistic) +
                     ", dof " + std::to_string(result.degrees_of_freedom) + ", p = " +
                     format_number(result.p_value) + ", pdf integral " + format_number(result.pdf_integral) +
                     (result.passed ? ": passed" : ": FAILED\n" + problems);
    return result;
}

std::string ChiSquareResult::table() const {
    const bool directions = domain.kind == Domain::Kind::Sphere || domain.kind == Domain::Kind::Hemisphere;
    const Grid grid = grid_for(domain, directions ? rows : columns);  // the resolution the test used
    std::ostringstream out;
    out << message << "\n\n"
        << "cell (column, row), " << (directions ? "phi" : "x") << " range, "
        << (directions ? "cos(theta)" : "y") << " range, observed, expected, (observed - expected) / sqrt(expected)\n";
    char line[200];
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            const std::size_t i = static_cast<std::size_t>(row) * columns + column;
            const double x0 = grid.x0 + column * grid.cell_width();
            const double y0 = grid.y0 + row * grid.cell_height();
            const double deviation =
                expected[i] > 0.0 ? (observed[i] - expected[i]) / std::sqrt(expected[i]) : (observed[i] > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
            std::snprintf(line, sizeof line, "(%3d,%3d)  [%8.4f, %8.4f)  [%8.4f, %8.4f)  %10.0f  %12.2f  %+8.2f\n",
                          column, row, x0, x0 + grid.cell_width(), y0, y0 + grid.cell_height(), observed[i],
                          expected[i], deviation);
            out << line;
        }
    }
    std::snprintf(line, sizeof line, "no sample returned:  %10.0f  %12.2f\n", static_cast<double>(samples_without_result),
                  expected_without_result);
    out << line;
    return out.str();
}

}  // namespace freezeray::stats
