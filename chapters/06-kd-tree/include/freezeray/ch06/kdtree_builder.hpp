// Building the KD-tree: the surface area heuristic's best split at every node, found and applied
// in O(N log N) (Wald and Havran, "On building fast kd-Trees for Ray Tracing, and on doing that
// in O(N log N)", IEEE Symposium on Interactive Ray Tracing 2006).
#pragma once

#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/ch06/kdtree_statistics.hpp"

#include <vector>

namespace freezeray::ch06 {

// Builds the tree over the triangles (global indices are positions in the vector). Triangles
// with a non-finite vertex are left out. A node becomes a leaf when it holds at most leaf_size
// triangles, at the depth limit, when no plane splits it, or when splitting does not pay: its
// best split costs more than four times the leaf with fewer than 16 triangles, or costs at least
// the leaf while max_unproductive_refinements such splits lie above it already (pbrt-v3,
// section 4.4.2). Deterministic: the same triangles give the same nodes. Fills `statistics`
// except build_milliseconds and the memory of the triangles.
KdTree build_kdtree(const std::vector<TriangleVertices>& triangles, const KdTreeSettings& settings,
                    KdTreeStatistics& statistics);

}  // namespace freezeray::ch06
