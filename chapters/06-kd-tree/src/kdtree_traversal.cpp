// The KD-tree's queries, on the walk of kdtree_traversal.hpp, one triangle at a time. Hits are
// those of brute force: the same
// watertight triangle test (Woop, Benthin and Wald 2013) on the same floats, cells found by a
// beam as wide as that test's rounding, and among hits an ulp apart brute force's own choice.
#include "freezeray/close_hits.hpp"
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

// Calls f(global triangle index) for each triangle of a leaf, after asking the memory system for
// all of their vertices at once (they are scattered over the triangle array).
template <typename F>
void for_each_triangle(const KdTree& tree, const KdTreeNode& leaf, const std::vector<TriangleVertices>& vertices,
                       F&& f) {
    const std::uint32_t count = leaf.triangle_count();
    const std::uint32_t* list = leaf_triangle_list(tree, leaf);
    for (std::uint32_t i = 0; i < count; ++i) __builtin_prefetch(&vertices[list[i]]);
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
        for_each_triangle(tree_, leaf, vertices_, [&](std::uint32_t triangle) {
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
    return brute_force_answer(ray, *walk, shear, close);
}
// END BOOK

std::optional<Hit> KdTreeAccelerator::brute_force_answer(const Ray& ray, const Walk& walk, const RayShear& shear,
                                                         CloseHits& close) const {
    if (close.empty()) return std::nullopt;
    const auto choice = close.brute_force_choice(
        ray, walk.inverse_direction, shear, brute_force_.mesh_bounds(), [&](std::uint32_t t) { return ids_[t].mesh; },
        [&](std::uint32_t t) -> const TriangleVertices& { return vertices_[t]; });
    if (!choice) return brute_force_.intersect(ray);  // its box test culled them all: its own answer
    const TriangleId& id = ids_[choice->triangle];
    return make_hit(*meshes_, id.mesh, id.triangle, choice->hit);
}

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

template <typename Counts>
bool KdTreeAccelerator::any_hit(const Ray& ray, Counts&& counts) const {
    const std::optional<Walk> walk = start_walk(tree_, ray);
    if (!walk) return false;
    const RayShear shear(ray.direction);
    bool found = false;
    NoCounting counter;
    traverse(tree_, ray, *walk, counter, [&](const KdTreeNode& leaf) {
        for_each_triangle(tree_, leaf, vertices_, [&](std::uint32_t triangle) {
            if (!counts(triangle)) return true;  // looked through
            const TriangleVertices& v = vertices_[triangle];
            // A hit counts, as in brute force, if the ray also meets its mesh's box.
            found = intersect_triangle(ray, shear, v.p0, v.p1, v.p2) && blocks(ray, *walk, triangle);
            return !found;  // the first hit answers the question
        });
        return found ? -std::numeric_limits<float>::infinity() : ray.tmax;
    });
    return found;
}

bool KdTreeAccelerator::occluded(const Ray& ray) const {
    return any_hit(ray, [](std::uint32_t) { return true; });
}

bool KdTreeAccelerator::occluded_by(const Ray& ray, const TriangleFlags& counted) const {
    return any_hit(ray, [&](std::uint32_t triangle) { return flagged(counted, triangle); });
}

}  // namespace freezeray::ch06
