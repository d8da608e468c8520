// The surface area heuristic (MacDonald and Booth 1990; Wald and Havran 2006).
#include "freezeray/ch06/surface_area_heuristic.hpp"

namespace freezeray::ch06 {

double surface_area(const Bounds3& box) {
    const double dx = static_cast<double>(box.max.x) - box.min.x;
    const double dy = static_cast<double>(box.max.y) - box.min.y;
    const double dz = static_cast<double>(box.max.z) - box.min.z;
    return 2.0 * (dx * dy + dy * dz + dz * dx);
}

std::size_t intersection_tests(const KdTreeSettings& settings, std::size_t triangle_count) {
    const std::size_t per_test = static_cast<std::size_t>(settings.triangles_per_test > 1 ? settings.triangles_per_test : 1);
    return (triangle_count + per_test - 1) / per_test;
}

// BOOK(sah-cost-model)
double leaf_cost(const KdTreeSettings& settings, std::size_t triangle_count) {
    return static_cast<double>(settings.intersection_cost) * static_cast<double>(intersection_tests(settings, triangle_count));
}

double split_cost(const KdTreeSettings& settings, const Bounds3& cell, int axis, float position,
                  std::size_t below_count, std::size_t above_count) {
    // EXERCISE(ch06/sah-cost): return the SAH cost of the split: the two children's surface areas relative to the cell's, their triangle counts, the costs of settings and the empty bonus when one child is empty
    Bounds3 below = cell, above = cell;
    below.max[axis] = position;
    above.min[axis] = position;
    const double inverse_area = 1.0 / surface_area(cell);
    const double probability_below = surface_area(below) * inverse_area;
    const double probability_above = surface_area(above) * inverse_area;
    const double bonus = (below_count == 0 || above_count == 0) ? settings.empty_bonus : 0.0;
    return settings.traversal_cost +
           (1.0 - bonus) * settings.intersection_cost *
               (probability_below * static_cast<double>(below_count) + probability_above * static_cast<double>(above_count));
    // END EXERCISE
}
// END BOOK

}  // namespace freezeray::ch06
