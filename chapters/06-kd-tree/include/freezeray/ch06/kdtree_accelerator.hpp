// The SAH KD-tree accelerator (`--accel kdtree`): built in O(N log N) (Wald and Havran 2006),
// traversed front to back (pbrt-v3, section 4.4.3), with hits identical to brute force.
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/ch06/kdtree_statistics.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace freezeray::ch06 {

// The work of one closest-hit query: the interior nodes and leaves it visited and the triangles
// it tested (a triangle in several leaves is tested, and counted, in each).
struct TraversalCounts {
    std::uint32_t interior_nodes = 0, leaves = 0, triangle_tests = 0;
};

class KdTreeAccelerator final : public Accelerator {
public:
    explicit KdTreeAccelerator(const KdTreeSettings& settings = {});

    void build(const std::vector<TriangleMesh>& meshes) override;

    // The closest hit, as BruteForceAccelerator finds it: the same triangle test on the same
    // floats, so the same t to the bit, and at equal t the triangle of lowest (mesh, triangle)
    // index. Rays with a non-finite or zero direction, a non-finite origin or a NaN tmax hit
    // nothing.
    std::optional<Hit> intersect(const Ray& ray) const override;
    bool occluded(const Ray& ray) const override;

    // What intersect(ray) does, counted (the traversal-cost integrator's images).
    TraversalCounts count_traversal(const Ray& ray) const;

    std::vector<std::pair<std::string, std::string>> describe() const override;
    // The nodes, the leaves' lists and the triangle copies (KdTreeStatistics::memory_bytes).
    std::optional<std::size_t> memory_bytes() const override { return statistics_.memory_bytes; }

    const KdTreeSettings& settings() const { return settings_; }
    const KdTreeStatistics& statistics() const { return statistics_; }
    const KdTree& tree() const { return tree_; }

private:
    // intersect, telling `counter` of its work (kdtree_traversal.cpp, the only user).
    template <typename Counter>
    std::optional<Hit> closest_hit(const Ray& ray, Counter& counter) const;

    KdTreeSettings settings_;
    const std::vector<TriangleMesh>* meshes_ = nullptr;
    std::vector<TriangleVertices> vertices_;  // per global triangle
    std::vector<TriangleId> ids_;             // per global triangle: its mesh and its index there
    BruteForceAccelerator brute_force_;       // answers the rare ray on which its culling and the tree differ
    KdTree tree_;
    KdTreeStatistics statistics_;
};

}  // namespace freezeray::ch06
