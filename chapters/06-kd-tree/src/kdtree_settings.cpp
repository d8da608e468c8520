// Reading the KD-tree's settings, and the automatic maximum depth.
#include "freezeray/ch06/kdtree_settings.hpp"

#include "freezeray/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace freezeray::ch06 {

// BOOK(kdtree-max-depth)
int effective_max_depth(const KdTreeSettings& settings, std::size_t triangle_count) {
    int depth = settings.max_depth;
    if (depth <= 0) {
        // pbrt-v3, section 4.4.2: deep enough for the tree to adapt to N triangles, shallow
        // enough to stop a runaway build (a cluster of triangles that no plane separates). With
        // triangles tested W at a time (chapter 07), the tree adapts to N / W packets' worth.
        const double per_test = static_cast<double>(std::max(settings.triangles_per_test, 1));
        const double n = std::max(static_cast<double>(std::max<std::size_t>(triangle_count, 1)) / per_test, 1.0);
        depth = static_cast<int>(std::lround(8.0 + 1.3 * std::log2(n)));
    }
    return std::clamp(depth, 1, TraversalStackSize);
}
// END BOOK

namespace {

int read_int(const Parameters& parameters, const std::string& key, int fallback, int min, int max) {
    const int value = parameters.get_int(key, fallback);
    if (value < min || value > max)
        throw InputError(parameters.where(key), "value " + std::to_string(value) + " is outside [" +
                                                    std::to_string(min) + ", " + std::to_string(max) + "]");
    return value;
}

}  // namespace

KdTreeSettings read_kdtree_settings(const Parameters& parameters) {
    KdTreeSettings s;
    constexpr float largest = std::numeric_limits<float>::max();
    constexpr float smallest_positive = std::numeric_limits<float>::min();
    s.traversal_cost = parameters.check_range(
        "traversal_cost", parameters.get_float("traversal_cost", s.traversal_cost), smallest_positive, largest);
    s.intersection_cost = parameters.check_range(
        "intersection_cost", parameters.get_float("intersection_cost", s.intersection_cost), smallest_positive, largest);
    // A bonus of 1 would make every empty split free, and the build would cut empty space forever.
    s.empty_bonus = parameters.check_range("empty_bonus", parameters.get_float("empty_bonus", s.empty_bonus), 0.0f,
                                           std::nextafter(1.0f, 0.0f));
    s.max_depth = read_int(parameters, "max_depth", s.max_depth, 0, TraversalStackSize);
    s.leaf_size = read_int(parameters, "leaf_size", s.leaf_size, 0, std::numeric_limits<int>::max());
    s.max_unproductive_refinements =
        read_int(parameters, "max_unproductive_refinements", s.max_unproductive_refinements, 0, TraversalStackSize);
    s.build_threads = read_int(parameters, "build_threads", s.build_threads, 0, 256);
    return s;
}

}  // namespace freezeray::ch06
