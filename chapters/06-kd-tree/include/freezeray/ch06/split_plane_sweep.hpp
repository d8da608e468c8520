// Finding the cheapest split plane of a node by one sweep over its sorted events (Wald and
// Havran 2006, section 4.3).
#pragma once

#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/ch06/split_events.hpp"

namespace freezeray::ch06 {

// The split of lowest SAH cost among the planes through the node's events, over all three axes,
// with the triangles lying in the plane put on the cheaper side. `cell` must have a positive
// surface area. Returns axis -1 when no plane can split the node: every candidate would give one
// child the whole cell and every triangle (a plane on the cell's face with nothing beyond it).
// Ties go to the first candidate in the order x, y, z, then by position, below before above.
SplitPlane find_split_plane(const NodeEvents& events, const Bounds3& cell, std::size_t triangle_count,
                            const KdTreeSettings& settings);

}  // namespace freezeray::ch06
