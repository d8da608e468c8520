// The recursive build: events sorted once at the root, then at every node one sweep for the
// best plane and one linear pass to divide the events (Wald and Havran 2006, section 4).
#include "freezeray/ch06/kdtree_builder.hpp"

#include "freezeray/ch06/split_events.hpp"
#include "freezeray/ch06/split_plane_sweep.hpp"
#include "freezeray/ch06/surface_area_heuristic.hpp"
#include "freezeray/error.hpp"

#include <cmath>
#include <stdexcept>

namespace freezeray::ch06 {

namespace {

bool is_finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

class KdTreeBuilder {
public:
    KdTreeBuilder(const std::vector<TriangleVertices>& triangles, const KdTreeSettings& settings,
                  KdTreeStatistics& statistics, KdTree& tree)
        : triangles_(triangles), settings_(settings), statistics_(statistics), tree_(tree),
          sides_(triangles.size(), Side::Both) {}

    void build() {
        NodeEvents events;
        Bounds3 bounds;
        std::size_t count = 0;
        for (std::size_t i = 0; i < triangles_.size(); ++i) {
            const TriangleVertices& t = triangles_[i];
            if (!is_finite(t.p0) || !is_finite(t.p1) || !is_finite(t.p2)) {
                ++statistics_.skipped_triangles;
                continue;
            }
            Bounds3 box;
            box.expand(t.p0);
            box.expand(t.p1);
            box.expand(t.p2);
            add_triangle_events(events, static_cast<std::uint32_t>(i), box);
            bounds.expand(box);
            ++count;
        }
        statistics_.triangles = triangles_.size();
        if (count == 0) return;  // no nodes: every ray misses
        sort_events(events);  // the only full sort of the build
        tree_.bounds = bounds;
        depth_limit_ = effective_max_depth(settings_, count);
        statistics_.depth_limit = depth_limit_;
        build_node(std::move(events), count, bounds, 0, 0);

        statistics_.nodes = tree_.nodes.size();
        statistics_.triangle_references = references_;
        if (statistics_.leaves > 0) statistics_.mean_leaf_depth = depth_sum_ / static_cast<double>(statistics_.leaves);
        const std::size_t full_leaves = statistics_.leaves - statistics_.empty_leaves;
        if (full_leaves > 0)
            statistics_.mean_triangles_per_leaf = static_cast<double>(references_) / static_cast<double>(full_leaves);
    }

private:
    // BOOK(kdtree-build-node)
    void build_node(NodeEvents events, std::size_t count, const Bounds3& cell, int depth, int unproductive) {
        if (tree_.nodes.size() > KdTreeNode::MaxIndex) throw std::length_error("kd-tree: more nodes than its 30-bit child index holds");
        if (count == 0 || count <= static_cast<std::size_t>(settings_.leaf_size) || depth >= depth_limit_ ||
            !(surface_area(cell) > 0.0)) {
            make_leaf(events, depth);
            return;
        }
        const SplitPlane plane = find_split_plane(events, cell, count, settings_);
        if (plane.axis < 0) {
            make_leaf(events, depth);
            return;
        }
        // pbrt-v3, section 4.4.2: a split that costs more than the leaf may still be worth it if
        // the splits below it pay; but not far more for a few triangles, and not too often.
        const double as_leaf = leaf_cost(settings_, count);
        if (plane.cost >= as_leaf) ++unproductive;
        if ((plane.cost > 4.0 * as_leaf && count < 16) || unproductive > settings_.max_unproductive_refinements) {
            make_leaf(events, depth);
            return;
        }

        ChildEvents children = split_events(events, plane, cell, triangles_, sides_);
        events = NodeEvents{};  // the parent's events are no longer needed
        Bounds3 below_cell = cell, above_cell = cell;
        below_cell.max[plane.axis] = plane.position;
        above_cell.min[plane.axis] = plane.position;

        // The below child follows its parent; the above child's index is known once the below
        // subtree is written (pbrt-v3, section 4.4.1).
        const std::size_t index = tree_.nodes.size();
        tree_.nodes.push_back(KdTreeNode::interior(plane.axis, plane.position, 0));
        build_node(std::move(children.below), children.below_count, below_cell, depth + 1, unproductive);
        tree_.nodes[index].set_above_child(static_cast<std::uint32_t>(tree_.nodes.size()));
        build_node(std::move(children.above), children.above_count, above_cell, depth + 1, unproductive);
    }
    // END BOOK

    void make_leaf(const NodeEvents& events, int depth) {
        const std::vector<std::uint32_t> triangles = triangles_of(events);
        if (triangles.size() > KdTreeNode::MaxIndex) throw std::length_error("kd-tree: a leaf holds more triangles than 2^30");
        const auto count = static_cast<std::uint32_t>(triangles.size());
        if (count == 1) {
            tree_.nodes.push_back(KdTreeNode::leaf(1, triangles[0]));  // inline, no list
        } else {
            tree_.nodes.push_back(KdTreeNode::leaf(count, static_cast<std::uint32_t>(tree_.leaf_triangles.size())));
            tree_.leaf_triangles.insert(tree_.leaf_triangles.end(), triangles.begin(), triangles.end());
        }
        ++statistics_.leaves;
        if (count == 0) ++statistics_.empty_leaves;
        references_ += count;
        depth_sum_ += depth;
        if (depth > statistics_.max_depth) statistics_.max_depth = depth;
    }

    const std::vector<TriangleVertices>& triangles_;
    const KdTreeSettings& settings_;
    KdTreeStatistics& statistics_;
    KdTree& tree_;
    std::vector<Side> sides_;
    int depth_limit_ = 1;
    std::size_t references_ = 0;
    double depth_sum_ = 0.0;
};

}  // namespace

KdTree build_kdtree(const std::vector<TriangleVertices>& triangles, const KdTreeSettings& settings,
                    KdTreeStatistics& statistics) {
    if (triangles.size() > 0xffffffffull) throw std::length_error("kd-tree: more than 2^32 triangles");
    statistics = KdTreeStatistics{};
    KdTree tree;
    KdTreeBuilder(triangles, settings, statistics, tree).build();
    tree.nodes.shrink_to_fit();
    tree.leaf_triangles.shrink_to_fit();
    statistics.memory_bytes = tree.nodes.size() * sizeof(KdTreeNode) + tree.leaf_triangles.size() * sizeof(std::uint32_t);
    return tree;
}

}  // namespace freezeray::ch06
