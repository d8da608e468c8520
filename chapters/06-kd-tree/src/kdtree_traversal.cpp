// Front-to-back traversal of the KD-tree (pbrt-v3, section 4.4.3; Havran, "Heuristic Ray
// Shooting Algorithms", PhD thesis, 2000): the ray's range is cut at each split plane, the child
// it passes first is visited first, the other is kept on a fixed stack, and the walk ends once
// the next cell begins beyond the closest hit. Hits are those of brute force: the same
// watertight triangle test (Woop, Benthin and Wald 2013) on the same floats, cells found by a
// beam as wide as that test's rounding, and among hits an ulp apart brute force's own choice.
#include "freezeray/ch06/close_hits.hpp"
#include "freezeray/ch06/kdtree_accelerator.hpp"
#include "freezeray/ch06/kdtree_traversal.hpp"

#include "freezeray/triangle_intersection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace freezeray::ch06 {

namespace {

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
constexpr float BeamRadiusScale = 0x1p-18f;

// A triangle's t is rounded too (its distance from the shear, then a division): a cell is still
// visited when it begins within this relative margin of the closest hit, plus twice the beam's
// radius in units of t (the watertight t errs by a few roundings of |vertex - origin| divided by
// the direction's largest component: PBR 3rd ed., section 3.9.6).
constexpr float DistanceMargin = 0x1p-18f;

// Once hits are known, a triangle is tested against a little more than CloseHits::limit(): the
// test compares its scaled distance with tmax before dividing (Woop et al. 2013, section 3.3), so
// a limit of exactly t could refuse a triangle whose rounded distance is t. Every triangle within
// the limit passes; which of them is the answer, CloseHits decides as brute force would.
constexpr float TieLimitFactor = 1.0f + 0x1p-20f;

bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A ray the traversal can follow: finite origin and direction, a direction that is not zero
// (whose inverse would be NaN on every axis), and a tmax above 0 (NaN is not).
bool is_traceable(const Ray& ray) {
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

Beam beam_around(const Ray& ray, const Bounds3& bounds) {
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

std::optional<Walk> start_walk(const KdTree& tree, const Ray& ray) {
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
// so that they cost nothing there), TraversalCounts for count_traversal.
struct NoCounting {
    void visit(const KdTreeNode&) {}
    void test() {}
};

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
    TraversalTask stack[TraversalStackSize];  // the build keeps the depth within it
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
            if (first && second) {
                stack[top++] = {order.far_child, std::max(t_min, second_from), t_max};
                index = order.near_child;
                t_max = std::min(t_max, first_until);
            } else if (first) {
                index = order.near_child;
            } else {
                index = order.far_child;
                t_min = std::max(t_min, second_from);
            }
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

// Calls f(global triangle index) for each triangle of a leaf.
template <typename F>
void for_each_triangle(const KdTree& tree, const KdTreeNode& leaf, F&& f) {
    const std::uint32_t count = leaf.triangle_count();
    if (count == 1) {
        f(leaf.one_triangle());
        return;
    }
    const std::uint32_t* list = tree.leaf_triangles.data() + leaf.triangle_offset();
    for (std::uint32_t i = 0; i < count; ++i)
        if (!f(list[i])) return;
}

}  // namespace

// BOOK(kdtree-intersect)
template <typename Counter>
std::optional<Hit> KdTreeAccelerator::closest_hit(const Ray& ray, Counter& counter) const {
    const std::optional<Walk> walk = start_walk(tree_, ray);
    if (!walk) return std::nullopt;
    const RayShear shear(ray.direction);
    Ray test = ray;
    CloseHits close;
    traverse(tree_, ray, *walk, counter, [&](const KdTreeNode& leaf) {
        for_each_triangle(tree_, leaf, [&](std::uint32_t triangle) {
            counter.test();
            const TriangleVertices& v = vertices_[triangle];
            if (const auto hit = intersect_triangle(test, shear, v.p0, v.p1, v.p2)) {
                close.add(triangle, *hit);
                test.tmax = std::min(ray.tmax, close.limit() * TieLimitFactor);
            }
            return true;
        });
        return close.limit();
    });
    if (close.empty()) return std::nullopt;
    const auto choice =
        close.brute_force_choice(ray, walk->inverse_direction, shear, vertices_, ids_, brute_force_.mesh_bounds());
    if (!choice) return brute_force_.intersect(ray);  // its box test culled them all: its own answer
    const TriangleId& id = ids_[choice->triangle];
    return make_hit(*meshes_, id.mesh, id.triangle, choice->hit);
}
// END BOOK

std::optional<Hit> KdTreeAccelerator::intersect(const Ray& ray) const {
    NoCounting counter;
    return closest_hit(ray, counter);
}

TraversalCounts KdTreeAccelerator::count_traversal(const Ray& ray) const {
    TraversalCounts counts;
    Counting counter{counts};
    closest_hit(ray, counter);
    return counts;
}

bool KdTreeAccelerator::occluded(const Ray& ray) const {
    const std::optional<Walk> walk = start_walk(tree_, ray);
    if (!walk) return false;
    const RayShear shear(ray.direction);
    bool found = false;
    NoCounting counter;
    traverse(tree_, ray, *walk, counter, [&](const KdTreeNode& leaf) {
        for_each_triangle(tree_, leaf, [&](std::uint32_t triangle) {
            const TriangleVertices& v = vertices_[triangle];
            // A hit counts, as in brute force, if the ray also meets its mesh's box.
            found = intersect_triangle(ray, shear, v.p0, v.p1, v.p2) &&
                    ray_intersects_bounds(ray, walk->inverse_direction, brute_force_.mesh_bounds()[ids_[triangle].mesh]);
            return !found;  // the first hit answers the question
        });
        return found ? -std::numeric_limits<float>::infinity() : ray.tmax;
    });
    return found;
}

}  // namespace freezeray::ch06
