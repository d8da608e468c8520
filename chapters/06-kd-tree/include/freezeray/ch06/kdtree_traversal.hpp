// The step of the front-to-back traversal at an interior node (pbrt-v3, section 4.4.3): which
// child the ray passes through first. The traversal itself is in kdtree_traversal.cpp
// (KdTreeAccelerator::intersect and occluded); this step is here, inline, as it runs at every node.
#pragma once

#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/ray.hpp"

#include <cstdint>

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
    // EXERCISE(ch06/near-far-order): return the child the ray passes through first (below when the direction grows along the split axis; for a ray parallel to the plane, the side of its origin, below when on the plane), the other second, and the ray's distance to the plane
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

}  // namespace freezeray::ch06
