// The surface area heuristic: the expected cost of tracing a random ray through a node, for a
// leaf and for a split (MacDonald and Booth, "Heuristics for ray tracing using space
// subdivision", The Visual Computer 6(3), 1990; Wald and Havran, "On building fast kd-Trees for
// Ray Tracing, and on doing that in O(N log N)", IEEE Symposium on Interactive Ray Tracing 2006).
#pragma once

#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/math.hpp"

#include <cstddef>

namespace freezeray::ch06 {

// The surface area of a box, in double precision (a box 1e20 across would overflow a float's).
// A flat box (zero extent along one axis) still has the area of its two faces.
double surface_area(const Bounds3& box);

// The intersection tests a ray makes in a leaf of n triangles: n, or ceil(n / W) when the
// triangles are tested W at a time (settings.triangles_per_test, chapter 07's packets).
std::size_t intersection_tests(const KdTreeSettings& settings, std::size_t triangle_count);

// The cost of making a node of n triangles a leaf: every ray that reaches it tests them all
// (intersection_tests of them).
double leaf_cost(const KdTreeSettings& settings, std::size_t triangle_count);

// The cost of splitting `cell` (positive surface area) at `position` along `axis`, with
// below_count tests in the child below the plane and above_count in the child above (triangles,
// or packets: see intersection_tests):
// C = C_traversal + (1 - bonus) (SA_below / SA N_below + SA_above / SA N_above) C_intersect,
// where SA_x / SA is the probability that a ray meeting the cell meets the child (Wald and Havran
// 2006, the SAH cost C_V(p) with pbrt-v3's form of the bonus), and the bonus (settings.empty_bonus) applies only when one child is empty.
double split_cost(const KdTreeSettings& settings, const Bounds3& cell, int axis, float position,
                  std::size_t below_count, std::size_t above_count);

}  // namespace freezeray::ch06
