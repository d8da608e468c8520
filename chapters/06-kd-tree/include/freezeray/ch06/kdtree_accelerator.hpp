// The SAH KD-tree accelerator (`--accel kdtree`): built in O(N log N) (Wald and Havran 2006),
// traversed front to back (pbrt-v3, section 4.4.3), with hits identical to brute force.
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/close_hits.hpp"
#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/ch06/kdtree_statistics.hpp"
#include "freezeray/ch06/kdtree_traversal.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace freezeray::ch06 {

// An accelerator whose closest-hit queries can be counted (the traversal-cost integrator's
// images): chapter 06's tree, and chapter 07's, which counts packet tests as triangle tests.
class CountedTraversal {
public:
    virtual ~CountedTraversal() = default;
    virtual TraversalCounts count_traversal(const Ray& ray) const = 0;
};

class KdTreeAccelerator final : public Accelerator, public CountedTraversal {
public:
    explicit KdTreeAccelerator(const KdTreeSettings& settings = {});

    void build(const std::vector<TriangleMesh>& meshes) override;

    // The closest hit, as BruteForceAccelerator finds it: the same triangle test on the same
    // floats, so the same t to the bit, and at equal t the triangle of lowest (mesh, triangle)
    // index. Rays with a non-finite or zero direction, a non-finite origin or a NaN tmax hit
    // nothing.
    std::optional<Hit> intersect(const Ray& ray) const override;
    bool occluded(const Ray& ray) const override;
    // occluded's walk, with the triangles whose flag is clear skipped before their test.
    bool occluded_by(const Ray& ray, const TriangleFlags& counted) const override;

    // What intersect(ray) does, counted (the traversal-cost integrator's images).
    TraversalCounts count_traversal(const Ray& ray) const override;

    std::vector<std::pair<std::string, std::string>> describe() const override;
    // The nodes, the leaves' lists and the triangle copies (KdTreeStatistics::memory_bytes).
    std::optional<std::size_t> memory_bytes() const override { return statistics_.memory_bytes; }

    const KdTreeSettings& settings() const { return settings_; }
    const KdTreeStatistics& statistics() const { return statistics_; }
    const KdTree& tree() const { return tree_; }

    // What an accelerator on the same tree needs to answer as this one does (chapter 07 repacks
    // the leaves, it does not rebuild): the triangles' vertices by global index; the hit brute
    // force reports among the close hits a walk found; whether a hit of `triangle` blocks a
    // shadow ray as it would in brute force (the ray must also meet its mesh's box).
    const std::vector<TriangleVertices>& triangle_vertices() const { return vertices_; }
    std::optional<Hit> brute_force_answer(const Ray& ray, const Walk& walk, const RayShear& shear, CloseHits& close) const;
    bool blocks(const Ray& ray, const Walk& walk, std::uint32_t triangle) const {
        return ray_intersects_bounds(ray, walk.inverse_direction, brute_force_.mesh_bounds()[ids_[triangle].mesh]);
    }
    // The flag of `triangle` (a global index) in per-mesh flags.
    bool flagged(const TriangleFlags& flags, std::uint32_t triangle) const {
        const TriangleId& id = ids_[triangle];
        return flags[id.mesh][id.triangle] != 0;
    }

private:
    // intersect, telling `counter` of its work (kdtree_traversal.cpp, the only user).
    template <typename Counter>
    std::optional<Hit> closest_hit(const Ray& ray, Counter& counter) const;
    // occluded and occluded_by: whether a triangle for which counts(global index) holds blocks the ray.
    template <typename Counts>
    bool any_hit(const Ray& ray, Counts&& counts) const;

    KdTreeSettings settings_;
    const std::vector<TriangleMesh>* meshes_ = nullptr;
    std::vector<TriangleVertices> vertices_;  // per global triangle
    std::vector<TriangleId> ids_;             // per global triangle: its mesh and its index there
    BruteForceAccelerator brute_force_;       // answers the rare ray on which its culling and the tree differ
    KdTree tree_;
    KdTreeStatistics statistics_;
};

}  // namespace freezeray::ch06
