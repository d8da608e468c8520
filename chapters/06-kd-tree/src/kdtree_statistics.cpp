// Printing a KD-tree's statistics.
#include "freezeray/ch06/kdtree_statistics.hpp"

#include <cstdio>

namespace freezeray::ch06 {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
    return buffer;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> KdTreeStatistics::describe() const {
    std::vector<std::pair<std::string, std::string>> lines;
    lines.emplace_back("build", format(build_threads == 1 ? "%.1f ms, %.0f triangles, %.0f thread" : "%.1f ms, %.0f triangles, %.0f threads",
                                       build_milliseconds, static_cast<double>(triangles), static_cast<double>(build_threads)));
    if (skipped_triangles > 0)
        lines.emplace_back("skipped", format("%.0f triangles with a non-finite vertex", static_cast<double>(skipped_triangles)));
    lines.emplace_back("nodes", format("%.0f (%.0f leaves, %.0f of them empty)", static_cast<double>(nodes),
                                       static_cast<double>(leaves), static_cast<double>(empty_leaves)));
    lines.emplace_back("depth", format("%.0f deepest leaf (limit %.0f), %.1f mean leaf depth", max_depth, depth_limit,
                                       mean_leaf_depth));
    const double per_triangle = triangles > 0 ? static_cast<double>(triangle_references) / static_cast<double>(triangles) : 0.0;
    lines.emplace_back("leaves", format("%.2f triangles per non-empty leaf, %.2f references per triangle",
                                        mean_triangles_per_leaf, per_triangle));
    lines.emplace_back("memory", format("%.2f MB", static_cast<double>(memory_bytes) / (1024.0 * 1024.0)));
    return lines;
}

}  // namespace freezeray::ch06
