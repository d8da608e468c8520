// Piecewise-constant distributions in one and two dimensions: sampling a tabulated function in
// proportion to its values by inverting its cumulative distribution (pbrt-v3, sections 13.3.1
// and 14.2.4). Chapter 03 uses them to choose lights by power and to sample environment maps.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace freezeray::ch03 {

// A density on [0, 1) proportional to a step function with n equal steps of values f[i] >= 0.
// When every value is zero the density is uniform (there is nothing better to follow).
class PiecewiseConstant1D {
public:
    explicit PiecewiseConstant1D(std::span<const float> values);

    std::size_t size() const { return values_.size(); }
    // The integral of the step function over [0, 1): the mean of the values.
    double integral() const { return integral_; }

    struct Continuous {
        float x;             // in [0, 1)
        float pdf;           // density at x
        std::size_t offset;  // the step x fell in
    };
    // A point x with density f(x) / integral, from u in [0, 1).
    Continuous sample_continuous(float u) const;
    float pdf(float x) const;

    // A step index i with probability f[i] / sum f, from u in [0, 1).
    std::size_t sample_discrete(float u) const;
    float discrete_probability(std::size_t i) const;

private:
    // The step that pdf() assigns to x in [0, 1).
    std::size_t step_of(float x) const;
    // The point (i + within) / n of step i, rounded to a float that step_of maps to i.
    float point_in_step(std::size_t i, double within) const;

    std::vector<float> values_;
    std::vector<double> cdf_;  // n + 1 entries, cdf_[0] = 0, cdf_[n] = 1
    double integral_ = 0.0;
};

// A density on [0, 1)^2 proportional to a table of values f[v * width + u] >= 0: a marginal
// density over rows (v) and a conditional density over columns (u) within each row.
class PiecewiseConstant2D {
public:
    PiecewiseConstant2D(std::span<const float> values, std::size_t width, std::size_t height);

    struct Sample {
        float u, v;  // in [0, 1)^2
        float pdf;   // density at (u, v)
    };
    Sample sample(float u0, float u1) const;
    float pdf(float u, float v) const;

private:
    std::vector<PiecewiseConstant1D> conditional_;  // one per row
    PiecewiseConstant1D marginal_;                  // over rows, from each row's integral
};

}  // namespace freezeray::ch03
