// The recursive build: events sorted once at the root, then at every node one sweep for the
// best plane and one linear pass to divide the events (Wald and Havran 2006, section 4). The
// two subtrees of a node near the root are built at the same time on two threads, each into
// its own arrays, and joined in depth-first order: the tree is the same for any thread count.
#include "freezeray/ch06/kdtree_builder.hpp"

#include "freezeray/ch06/split_events.hpp"
#include "freezeray/ch06/split_plane_sweep.hpp"
#include "freezeray/ch06/surface_area_heuristic.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <future>
#include <stdexcept>
#include <thread>

namespace freezeray::ch06 {

namespace {

bool is_finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// A subtree in its own arrays: node 0 is its root, child and leaf-list indices count from 0.
struct Subtree {
    std::vector<KdTreeNode> nodes;
    std::vector<std::uint32_t> leaf_triangles;
    // What the statistics need of its leaves.
    std::size_t leaves = 0, empty_leaves = 0, references = 0;
    double depth_sum = 0.0;
    int max_depth = 0;

    // Appends `other` after this subtree's nodes, moving its indices by where it now starts.
    void append(const Subtree& other) {
        const auto node_base = static_cast<std::uint32_t>(nodes.size());
        const auto list_base = static_cast<std::uint32_t>(leaf_triangles.size());
        if (nodes.size() + other.nodes.size() > KdTreeNode::MaxIndex)
            throw std::length_error("kd-tree: more nodes than its 30-bit child index holds");
        for (KdTreeNode node : other.nodes) {
            if (!node.is_leaf())
                node.set_above_child(node.above_child() + node_base);
            else if (node.triangle_count() != 1)  // an empty leaf's offset too: where its list would start
                node = KdTreeNode::leaf(node.triangle_count(), node.triangle_offset() + list_base);
            nodes.push_back(node);
        }
        leaf_triangles.insert(leaf_triangles.end(), other.leaf_triangles.begin(), other.leaf_triangles.end());
        leaves += other.leaves;
        empty_leaves += other.empty_leaves;
        references += other.references;
        depth_sum += other.depth_sum;
        max_depth = std::max(max_depth, other.max_depth);
    }
};

class KdTreeBuilder {
public:
    KdTreeBuilder(const std::vector<TriangleVertices>& triangles, const KdTreeSettings& settings,
                  KdTreeStatistics& statistics, KdTree& tree)
        : triangles_(triangles), settings_(settings), statistics_(statistics), tree_(tree) {}

    void build() {
        NodeEvents events;
        Bounds3 bounds;
        std::size_t count = 0;
        // In increasing triangle order, as sort_events_added_in_triangle_order needs.
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
        tree_.bounds = bounds;
        depth_limit_ = effective_max_depth(settings_, count);
        statistics_.depth_limit = depth_limit_;
        parallel_depth_ = parallel_depth(settings_.build_threads);
        sort_root_events(events);

        Subtree tree;
        std::vector<Side> sides(triangles_.size(), Side::Both);
        build_node(std::move(events), count, bounds, 0, 0, tree, sides);
        statistics_.build_threads = threads_used_.load();

        tree_.nodes = std::move(tree.nodes);
        tree_.leaf_triangles = std::move(tree.leaf_triangles);
        statistics_.nodes = tree_.nodes.size();
        statistics_.leaves = tree.leaves;
        statistics_.empty_leaves = tree.empty_leaves;
        statistics_.max_depth = tree.max_depth;
        statistics_.triangle_references = tree.references;
        if (tree.leaves > 0) statistics_.mean_leaf_depth = tree.depth_sum / static_cast<double>(tree.leaves);
        const std::size_t full_leaves = tree.leaves - tree.empty_leaves;
        if (full_leaves > 0)
            statistics_.mean_triangles_per_leaf = static_cast<double>(tree.references) / static_cast<double>(full_leaves);
    }

private:
    // A node this small is built on its own thread: starting a thread would cost more than it saves.
    static constexpr std::size_t MinimumParallelTriangles = 4096;

    // Nodes above this depth build their below subtree on a thread of its own: 2^depth subtrees
    // share the cores, a few per core, so that an unbalanced split leaves no core idle for long.
    static int parallel_depth(int build_threads) {
        int threads = build_threads > 0 ? build_threads : static_cast<int>(std::thread::hardware_concurrency());
        if (threads <= 1) return 0;
        int depth = 0;
        while ((1 << depth) < threads) ++depth;
        return depth + 2;
    }

    // The only full sort of the build: the three axes at once when the build may use threads.
    void sort_root_events(NodeEvents& events) {
        if (parallel_depth_ == 0 || events[0].size() < 2 * MinimumParallelTriangles) {
            for (auto& list : events) sort_events_added_in_triangle_order(list);
            return;
        }
        auto x = std::async(std::launch::async, [&] { sort_events_added_in_triangle_order(events[0]); });
        auto y = std::async(std::launch::async, [&] { sort_events_added_in_triangle_order(events[1]); });
        sort_events_added_in_triangle_order(events[2]);
        x.get();
        y.get();
    }

    // BOOK(kdtree-build-node)
    void build_node(NodeEvents events, std::size_t count, const Bounds3& cell, int depth, int unproductive,
                    Subtree& out, std::vector<Side>& sides) {
        if (out.nodes.size() > KdTreeNode::MaxIndex) throw std::length_error("kd-tree: more nodes than its 30-bit child index holds");
        if (count == 0 || count <= static_cast<std::size_t>(settings_.leaf_size) || depth >= depth_limit_ ||
            !(surface_area(cell) > 0.0)) {
            make_leaf(events, depth, out);
            return;
        }
        const SplitPlane plane = find_split_plane(events, cell, count, settings_);
        if (plane.axis < 0) {
            make_leaf(events, depth, out);
            return;
        }
        // pbrt-v3, section 4.4.2: a split that costs more than the leaf may still be worth it if
        // the splits below it pay; but not far more for a few triangles, and not too often.
        const double as_leaf = leaf_cost(settings_, count);
        if (plane.cost >= as_leaf) ++unproductive;
        if ((plane.cost > 4.0 * as_leaf && count < 16) || unproductive > settings_.max_unproductive_refinements) {
            make_leaf(events, depth, out);
            return;
        }

        ChildEvents children = split_events(events, plane, cell, triangles_, sides);
        events = NodeEvents{};  // the parent's events are no longer needed
        Bounds3 below_cell = cell, above_cell = cell;
        below_cell.max[plane.axis] = plane.position;
        above_cell.min[plane.axis] = plane.position;

        // The below child follows its parent; the above child's index is known once the below
        // subtree is written (pbrt-v3, section 4.4.1).
        const std::size_t index = out.nodes.size();
        out.nodes.push_back(KdTreeNode::interior(plane.axis, plane.position, 0));
        if (depth < parallel_depth_ && count >= MinimumParallelTriangles) {
            build_children_in_parallel(children, below_cell, above_cell, depth, unproductive, out, index, sides);
            return;
        }
        build_node(std::move(children.below), children.below_count, below_cell, depth + 1, unproductive, out, sides);
        out.nodes[index].set_above_child(static_cast<std::uint32_t>(out.nodes.size()));
        build_node(std::move(children.above), children.above_count, above_cell, depth + 1, unproductive, out, sides);
    }
    // END BOOK

    // The two subtrees at once, the below one on a new thread (with scratch space of its own:
    // a triangle the plane cuts is in both), the above one on this thread, then both joined
    // after their parent in depth-first order.
    void build_children_in_parallel(ChildEvents& children, const Bounds3& below_cell, const Bounds3& above_cell,
                                    int depth, int unproductive, Subtree& out, std::size_t index,
                                    std::vector<Side>& sides) {
        ++threads_used_;
        auto below = std::async(std::launch::async, [&, events = std::move(children.below)]() mutable {
            Subtree subtree;
            std::vector<Side> own_sides(triangles_.size(), Side::Both);
            build_node(std::move(events), children.below_count, below_cell, depth + 1, unproductive, subtree, own_sides);
            return subtree;
        });
        Subtree above;
        build_node(std::move(children.above), children.above_count, above_cell, depth + 1, unproductive, above, sides);
        out.append(below.get());  // rethrows what the thread threw
        out.nodes[index].set_above_child(static_cast<std::uint32_t>(out.nodes.size()));
        out.append(above);
    }

    void make_leaf(const NodeEvents& events, int depth, Subtree& out) const {
        const std::vector<std::uint32_t> triangles = triangles_of(events);
        if (triangles.size() > KdTreeNode::MaxIndex) throw std::length_error("kd-tree: a leaf holds more triangles than 2^30");
        const auto count = static_cast<std::uint32_t>(triangles.size());
        if (count == 1) {
            out.nodes.push_back(KdTreeNode::leaf(1, triangles[0]));  // inline, no list
        } else {
            out.nodes.push_back(KdTreeNode::leaf(count, static_cast<std::uint32_t>(out.leaf_triangles.size())));
            out.leaf_triangles.insert(out.leaf_triangles.end(), triangles.begin(), triangles.end());
        }
        ++out.leaves;
        if (count == 0) ++out.empty_leaves;
        out.references += count;
        out.depth_sum += depth;
        out.max_depth = std::max(out.max_depth, depth);
    }

    const std::vector<TriangleVertices>& triangles_;
    const KdTreeSettings& settings_;
    KdTreeStatistics& statistics_;
    KdTree& tree_;
    int depth_limit_ = 1;
    int parallel_depth_ = 0;
    std::atomic<int> threads_used_{1};
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
