// Piecewise-constant distributions (pbrt-v3, sections 13.3.1 and 14.2.4).
#include "freezeray/ch03/piecewise_constant.hpp"

#include "freezeray/math.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch03 {

PiecewiseConstant1D::PiecewiseConstant1D(std::span<const float> values)
    : values_(values.begin(), values.end()), cdf_(values.size() + 1, 0.0) {
    const std::size_t n = values_.size();
    // The running sum is kept in double precision: an environment map may hold a sun a million
    // times brighter than the sky beside thousands of dark pixels.
    for (std::size_t i = 0; i < n; ++i) cdf_[i + 1] = cdf_[i] + static_cast<double>(values_[i]) / static_cast<double>(n);
    integral_ = cdf_[n];
    if (integral_ > 0.0) {
        for (std::size_t i = 1; i <= n; ++i) cdf_[i] /= integral_;
    } else {
        for (std::size_t i = 1; i <= n; ++i) cdf_[i] = static_cast<double>(i) / static_cast<double>(n);
    }
    cdf_[n] = 1.0;
}

// The index i with cdf_[i] <= u < cdf_[i + 1]. Steps of zero width (zero values) are never
// chosen, so the chosen step always has a positive value.
static std::size_t find_step(const std::vector<double>& cdf, double u) {
    const auto it = std::upper_bound(cdf.begin(), cdf.end(), u);
    const auto i = static_cast<std::size_t>(it - cdf.begin()) - 1;
    return std::min(i, cdf.size() - 2);
}

// (i + within) / n rounded to float, kept inside step i as pdf() sees it. Plain rounding can
// carry x onto the first float of the next step (or below the first of this one), where pdf()
// looks up another step, possibly one of value zero: about 3 samples in a million did so with
// 3 to 1000 steps (tests/chi2/test_ch03_lights.cpp catches them). step_of is monotone in x, so the
// loops end within a few floats.
float PiecewiseConstant1D::point_in_step(std::size_t i, double within) const {
    const auto n = static_cast<double>(size());
    float x = std::min(static_cast<float>((static_cast<double>(i) + within) / n), OneMinusEpsilon);
    while (x > 0.0f && step_of(x) > i) x = std::nextafter(x, 0.0f);
    while (step_of(x) < i) x = std::nextafter(x, 1.0f);
    return x;
}

// BOOK(sample-piecewise-constant)
PiecewiseConstant1D::Continuous PiecewiseConstant1D::sample_continuous(float u) const {
    const std::size_t i = find_step(cdf_, u);
    const double width = cdf_[i + 1] - cdf_[i];
    const double within = width > 0.0 ? (u - cdf_[i]) / width : 0.0;  // where u falls inside the step
    const float x = point_in_step(i, within);  // (i + within) / n
    const float density = integral_ > 0.0 ? static_cast<float>(static_cast<double>(values_[i]) / integral_) : 1.0f;
    return {x, density, i};
}
// END BOOK

std::size_t PiecewiseConstant1D::step_of(float x) const {
    return std::min(static_cast<std::size_t>(x * static_cast<float>(size())), size() - 1);
}

float PiecewiseConstant1D::pdf(float x) const {
    if (!(x >= 0.0f && x < 1.0f)) return 0.0f;
    const std::size_t i = step_of(x);
    if (integral_ <= 0.0) return 1.0f;
    return static_cast<float>(static_cast<double>(values_[i]) / integral_);
}

std::size_t PiecewiseConstant1D::sample_discrete(float u) const { return find_step(cdf_, u); }

float PiecewiseConstant1D::discrete_probability(std::size_t i) const {
    return static_cast<float>(cdf_[i + 1] - cdf_[i]);
}

PiecewiseConstant2D::PiecewiseConstant2D(std::span<const float> values, std::size_t width, std::size_t height)
    : marginal_([&] {
          conditional_.reserve(height);
          std::vector<float> row_integrals(height);
          for (std::size_t v = 0; v < height; ++v) {
              conditional_.emplace_back(values.subspan(v * width, width));
              row_integrals[v] = static_cast<float>(conditional_.back().integral());
          }
          return PiecewiseConstant1D(row_integrals);
      }()) {}

PiecewiseConstant2D::Sample PiecewiseConstant2D::sample(float u0, float u1) const {
    // First the row, from the marginal density; then the column within that row (pbrt-v3, 14.2.4).
    const PiecewiseConstant1D::Continuous v = marginal_.sample_continuous(u1);
    const PiecewiseConstant1D::Continuous u = conditional_[v.offset].sample_continuous(u0);
    return {u.x, v.x, u.pdf * v.pdf};
}

float PiecewiseConstant2D::pdf(float u, float v) const {
    if (!(v >= 0.0f && v < 1.0f)) return 0.0f;
    const auto row = std::min(static_cast<std::size_t>(v * static_cast<float>(conditional_.size())),
                              conditional_.size() - 1);
    return marginal_.pdf(v) * conditional_[row].pdf(u);
}

}  // namespace freezeray::ch03
