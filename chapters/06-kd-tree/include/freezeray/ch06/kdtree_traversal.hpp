// The step of the front-to-back traversal at an interior node (pbrt-v3, section 4.4.3): which
// child the ray passes through first. The traversal itself is in kdtree_traversal.cpp
// (KdTreeAccelerator::intersect and occluded).
#pragma once

#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/ray.hpp"

#include <cstdint>

namespace freezeray::ch06 {

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
ChildOrder order_children(const KdTreeNode& node, std::uint32_t index, const Ray& ray, const Vec3& inverse_direction);

}  // namespace freezeray::ch06
