// Front-to-back traversal of the KD-tree (pbrt-v3, section 4.4.3; Havran, "Heuristic Ray
// Shooting Algorithms", PhD thesis, 2000): the ray's range is cut at each split plane, the child
// it passes first is visited first, the other is kept on a fixed stack, and the walk ends once
// the next cell begins beyond the closest hit. Here, inline, as templates over what is done in a
// leaf: chapter 06's accelerator tests a leaf's triangles one by one (kdtree_traversal.cpp),
// chapter 07's a packet of them at once, on the same walk.
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/ray.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace freezeray::ch06 {

// BOOK(order-children)
// The children of an interior node in the order the ray passes through them, and where it
// crosses the split plane.
struct ChildOrder {
    std::uint32_t near_child, far_child;
    float t_plane;  // (split - origin) / direction along the split axis: negative when behind,
                    // infinite for a ray parallel to the plane, NaN for one lying in it
};

// The near child is the one the ray is in before it crosses the plane: below when the direction
// grows along the split axis, above when it shrinks. A ray parallel to the plane never crosses
// it: its near child is its origin's side (below for an origin on the plane). For a ray heading
// away from the plane (t_plane < 0) the near child is the one it has left, and only the far one
// matters. `index` is the node's own index (its below child follows it).
inline ChildOrder order_children(const KdTreeNode& node, std::uint32_t index, const Ray& ray, const Vec3& inverse_direction) {
    // EXERCISE(ch06/near-far-order): order the children of an interior node for the ray as book chapter 06, "Traversal", does, including a ray parallel to the plane and one starting on it (see order_children's comment), with the ray's distance to the plane
    const int axis = node.split_axis();
    const float split = node.split_position();
    const float t_plane = (split - ray.origin[axis]) * inverse_direction[axis];
    const float d = ray.direction[axis];
    const bool below_first = d > 0.0f || (d == 0.0f && ray.origin[axis] <= split);
    const std::uint32_t below = index + 1, above = node.above_child();
    return below_first ? ChildOrder{below, above, t_plane} : ChildOrder{above, below, t_plane};
    // END EXERCISE
}
// END BOOK

// The watertight test decides in floating point whether a ray passes inside a triangle, from the
// vertices taken relative to the ray's origin and sheared (Woop et al. 2013, section 3): its answer
// is exact for the rounded coordinates, so a ray passing a few roundings of |vertex - origin|
// outside a triangle may hit it (and one as close inside may miss it). Seen from 1e5 away, a
// triangle is blurred by about 0.01. Brute force takes those answers as they come; to find the
// same triangles the traversal follows a beam around the ray and visits every cell the beam
// touches, of radius 2^-18 (64 roundings) times the distance from the origin to the farthest
// corner of the scene's bounds, which bounds every |vertex - origin| wherever the origin is. The
// beam also covers the rounding of the distances to the split planes: a ray through the corner
// where two planes meet, or through a shared vertex or edge lying in a plane, visits every cell
// there.
inline constexpr float BeamRadiusScale = 0x1p-18f;

// A triangle's t is rounded too (its distance from the shear, then a division): a cell is still
// visited when it begins within this relative margin of the closest hit, plus twice the beam's
// radius in units of t (the watertight t errs by a few roundings of |vertex - origin| divided by
// the direction's largest component: PBR 3rd ed., section 3.9.6).
inline constexpr float DistanceMargin = 0x1p-18f;

// Once hits are known, a triangle is tested against a little more than CloseHits::limit(): the
// test compares its scaled distance with tmax before dividing (Woop et al. 2013, section 3.3), so
// a limit of exactly t could refuse a triangle whose rounded distance is t. Every triangle within
// the limit passes; which of them is the answer, CloseHits decides as brute force would.
inline constexpr float TieLimitFactor = 1.0f + 0x1p-20f;

inline bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A ray the traversal can follow: finite origin and direction, a direction that is not zero
// (whose inverse would be NaN on every axis), and a tmax above 0 (NaN is not).
inline bool is_traceable(const Ray& ray) {
    return is_finite(ray.origin) && is_finite(ray.direction) &&
           (ray.direction.x != 0.0f || ray.direction.y != 0.0f || ray.direction.z != 0.0f) && ray.tmax > 0.0f;
}

// BOOK(traversal-beam)
// The beam around a ray (see BeamRadiusScale): its radius in world units, and the slack it adds to
// distances along the ray.
struct Beam {
    float radius;
    float t_slack;
};

inline Beam beam_around(const Ray& ray, const Bounds3& bounds) {
    float farthest = 0.0f, largest_direction = 0.0f;
    for (int axis = 0; axis < 3; ++axis) {
        farthest = std::max({farthest, std::abs(bounds.min[axis] - ray.origin[axis]),
                             std::abs(bounds.max[axis] - ray.origin[axis])});
        largest_direction = std::max(largest_direction, std::abs(ray.direction[axis]));
    }
    const float radius = BeamRadiusScale * farthest;
    return {radius, 2.0f * radius / largest_direction};
}

// Where the walk of a ray starts: its inverse direction, its beam, and the range of t in which
// the beam is inside the tree's bounds. Nothing for a ray the traversal cannot follow, or one
// that misses the bounds.
struct Walk {
    Vec3 inverse_direction;
    Beam beam;
    float t_enter, t_exit;
};

inline std::optional<Walk> start_walk(const KdTree& tree, const Ray& ray) {
    if (tree.nodes.empty() || !is_traceable(ray)) return std::nullopt;
    Walk walk{1.0f / ray.direction, {}, 0.0f, 0.0f};
    if (!clip_ray_to_bounds(ray, walk.inverse_direction, tree.bounds, walk.t_enter, walk.t_exit)) return std::nullopt;
    walk.beam = beam_around(ray, tree.bounds);
    walk.t_enter = std::max(0.0f, walk.t_enter - walk.beam.t_slack);
    walk.t_exit += walk.beam.t_slack;
    return walk;
}
// END BOOK

// The counters of the traversal's work: none for intersect and occluded (a template parameter,
// so that they cost nothing there); kdtree_traversal.cpp counts for count_traversal.
struct NoCounting {
    void visit(const KdTreeNode&) {}
    void test() {}
};

// The work of one closest-hit query: the interior nodes and leaves it visited and the triangles
// it tested (a triangle in several leaves is tested, and counted, in each; chapter 07 counts a
// packet as one test).
struct TraversalCounts {
    std::uint32_t interior_nodes = 0, leaves = 0, triangle_tests = 0;
};

// The counter of count_traversal: every node visited and every test.
struct Counting {
    TraversalCounts& counts;
    void visit(const KdTreeNode& node) { ++(node.is_leaf() ? counts.leaves : counts.interior_nodes); }
    void test() { ++counts.triangle_tests; }
};


struct TraversalTask {
    std::uint32_t node;
    float t_min, t_max;
};

// BOOK(kdtree-traverse)
// Visits the leaves the beam around the ray's range [walk.t_enter, walk.t_exit] touches, in the
// order the ray enters them. visit_leaf(leaf) returns the distance beyond which nothing is wanted (the
// closest hit so far, or -infinity to stop); cells the beam reaches only beyond it are skipped.
// `counter` is told of every node visited (NoCounting, for the queries themselves, does nothing).
template <typename Counter, typename VisitLeaf>
void traverse(const KdTree& tree, const Ray& ray, const Walk& walk, Counter& counter, VisitLeaf&& visit_leaf) {
    const Vec3& inverse_direction = walk.inverse_direction;
    const Beam& beam = walk.beam;
    float t_min = walk.t_enter, t_max = walk.t_exit;
    // Per axis: whether the ray is parallel to planes across it, and how long the beam takes
    // to cross one.
    bool parallel[3];
    float crossing[3];
    for (int axis = 0; axis < 3; ++axis) {
        parallel[axis] = std::isinf(inverse_direction[axis]);
        crossing[axis] = beam.radius * std::abs(inverse_direction[axis]);
    }
    // The build makes every node at depth TraversalStackSize or deeper a leaf, and the walk pushes
    // at most one entry per level: at an interior node of depth d the stack holds at most d
    // entries, so the far child written at its top always fits.
    TraversalTask stack[TraversalStackSize];
    int top = 0;
    std::uint32_t index = 0;
    float skip_after = std::numeric_limits<float>::infinity();
    for (;;) {
        // A cell that begins beyond what is wanted is skipped. The cells still on the stack
        // usually begin later still, but not always (the beam's ranges overlap, and a ray
        // parallel to a plane gives both children one range): they are checked, not dropped.
        if (t_min > skip_after) {
            if (top == 0) break;
            --top;
            index = stack[top].node;
            t_min = stack[top].t_min;
            t_max = stack[top].t_max;
            continue;
        }
        const KdTreeNode& node = tree.nodes[index];
        counter.visit(node);
        if (!node.is_leaf()) {
            // The above child lies far from its parent in memory: ask for it now, whichever child
            // the ray takes first (the below child follows its parent, usually in the same line).
            __builtin_prefetch(&tree.nodes[node.above_child()]);
            const ChildOrder order = order_children(node, index, ray, inverse_direction);
            const int axis = node.split_axis();
            if (parallel[axis]) {
                // Parallel to the plane: the origin's side all along, the other too if the beam
                // reaches across (a ray lying in the plane gives t_plane NaN: 0 times infinity).
                if (std::abs(ray.origin[axis] - node.split_position()) <= beam.radius)
                    stack[top++] = {order.far_child, t_min, t_max};
                index = order.near_child;
                continue;
            }
            // The beam touches the first child until it is past the plane by its radius, the
            // second from when it is that close to the plane.
            const float dt = crossing[axis];
            const float first_until = order.t_plane + dt, second_from = order.t_plane - dt;
            const bool first = first_until >= t_min, second = second_from <= t_max;
            // Three cases: both children (the near one now, the far one on the stack), the near
            // one alone, or the far one alone (when the first is false). Written with selects, not
            // branches: which case comes next is a coin toss for incoherent rays, and a
            // mispredicted branch costs more than the work it skips (book chapter 06, "Branches
            // or selects"). The far child is written to the stack every time and kept only when
            // both are visited. With the near child alone, first_until >= t_max (the second is
            // false: second_from > t_max), so the min leaves t_max as it is.
            const float far_from = std::max(t_min, second_from);
            stack[top] = {order.far_child, far_from, t_max};
            top += static_cast<int>(first && second);
            index = first ? order.near_child : order.far_child;
            t_min = first ? t_min : far_from;
            t_max = first ? std::min(t_max, first_until) : t_max;
            continue;
        }
        const float wanted = visit_leaf(node);
        skip_after = wanted * (1.0f + DistanceMargin) + beam.t_slack;
        if (top == 0) break;
        --top;
        index = stack[top].node;
        t_min = stack[top].t_min;
        t_max = stack[top].t_max;
    }
}
// END BOOK

}  // namespace freezeray::ch06
