// The surface area heuristic: the expected cost of tracing a random ray through a node, for a
// leaf and for a split (MacDonald and Booth, "Heuristics for ray tracing using space
// subdivision", The Visual Computer 6(3), 1990; Wald and Havran, "On building fast kd-Trees for
// Ray Tracing, and on doing that in O(N log N)", IEEE Symposium on Interactive Ray Tracing 2006).
// Defined here, inline: the build's sweep evaluates a split's cost at every event, millions of
// times on a large scene, and a call to another file for each cost a tenth of the build.
#pragma once

#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/math.hpp"

#include <cstddef>

namespace freezeray::ch06 {

// The surface area of a box, in double precision (a box 1e20 across would overflow a float's).
// A flat box (zero extent along one axis) still has the area of its two faces.
inline double surface_area(const Bounds3& box) {
    const double dx = static_cast<double>(box.max.x) - box.min.x;
    const double dy = static_cast<double>(box.max.y) - box.min.y;
    const double dz = static_cast<double>(box.max.z) - box.min.z;
    return 2.0 * (dx * dy + dy * dz + dz * dx);
}

// The intersection tests a ray makes in a leaf of n triangles: n, or ceil(n / W) when the
// triangles are tested W at a time (settings.triangles_per_test, chapter 07's packets).
inline std::size_t intersection_tests(const KdTreeSettings& settings, std::size_t triangle_count) {
    if (settings.triangles_per_test <= 1) return triangle_count;  // the common case, without a division
    const auto per_test = static_cast<std::size_t>(settings.triangles_per_test);
    return (triangle_count + per_test - 1) / per_test;
}

// The cost of making a node of n triangles a leaf: every ray that reaches it tests them all
// (intersection_tests of them).
// BOOK(sah-cost-model)
inline double leaf_cost(const KdTreeSettings& settings, std::size_t triangle_count) {
    return static_cast<double>(settings.intersection_cost) * static_cast<double>(intersection_tests(settings, triangle_count));
}

// The cost of splitting one cell (positive surface area) at a plane. What depends on the cell
// alone, its extents and the inverse of its area, is computed once: a sweep costs thousands of
// planes of one cell, and a division per plane was a tenth of the sweep's time on Sponza.
class SplitCostModel {
public:
    SplitCostModel(const KdTreeSettings& settings, const Bounds3& cell);

    // The cost of the split at `position` along `axis`, with below_count tests in the child below
    // the plane and above_count in the child above (triangles, or packets: see
    // intersection_tests):
    // C = C_traversal + (1 - bonus) (SA_below / SA N_below + SA_above / SA N_above) C_intersect,
    // where SA_x / SA is the probability that a ray meeting the cell meets the child (Wald and
    // Havran 2006, the SAH cost C_V(p) with pbrt-v3's form of the bonus), and the bonus
    // (settings.empty_bonus) applies only when one child is empty.
    double cost(int axis, float position, std::size_t below_count, std::size_t above_count) const;

private:
    const KdTreeSettings& settings_;
    Bounds3 cell_;
    double extent_[3];     // the cell's extent along each axis, in double precision
    double inverse_area_;  // 1 / surface_area(cell)
};

inline SplitCostModel::SplitCostModel(const KdTreeSettings& settings, const Bounds3& cell)
    : settings_(settings), cell_(cell), inverse_area_(1.0 / surface_area(cell)) {
    for (int k = 0; k < 3; ++k) extent_[k] = static_cast<double>(cell.max[k]) - cell.min[k];
}

inline double SplitCostModel::cost(int axis, float position, std::size_t below_count, std::size_t above_count) const {
    // EXERCISE(ch06/sah-cost): the SAH cost of splitting the cell at this plane, book chapter 06, "The surface area heuristic", with the settings' costs and the empty bonus when one child is empty (see the comment of cost)
    // The children's extents: the cell's, but along the axis up to the plane and from it.
    double below[3] = {extent_[0], extent_[1], extent_[2]};
    double above[3] = {extent_[0], extent_[1], extent_[2]};
    below[axis] = static_cast<double>(position) - cell_.min[axis];
    above[axis] = static_cast<double>(cell_.max[axis]) - position;
    auto area = [](const double* d) { return 2.0 * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0]); };
    const double probability_below = area(below) * inverse_area_;
    const double probability_above = area(above) * inverse_area_;
    const double bonus = (below_count == 0 || above_count == 0) ? settings_.empty_bonus : 0.0;
    return settings_.traversal_cost +
           (1.0 - bonus) * settings_.intersection_cost *
               (probability_below * static_cast<double>(below_count) + probability_above * static_cast<double>(above_count));
    // END EXERCISE
}

// The cost of one split, for a caller that costs a single plane of a cell.
inline double split_cost(const KdTreeSettings& settings, const Bounds3& cell, int axis, float position,
                         std::size_t below_count, std::size_t above_count) {
    return SplitCostModel(settings, cell).cost(axis, position, below_count, above_count);
}
// END BOOK

}  // namespace freezeray::ch06
