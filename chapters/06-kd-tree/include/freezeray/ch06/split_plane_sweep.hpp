// Finding the cheapest split plane of a node by one sweep over its sorted events (Wald and
// Havran 2006, section 4.3).
#pragma once

#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/ch06/split_events.hpp"

namespace freezeray::ch06 {

// The split of lowest SAH cost among the planes through the node's events, over all three axes
// (none along an axis the cell is flat along), with the triangles lying in the plane put on the
// cheaper side. For a plane at p, the triangles below are those whose box starts before p (one
// lying in a plane of its own: that plane is before p), those above are those whose box ends
// after p (lying: after p), and those lying in p itself go below (planar_below) or above; both
// choices are costed, by the cell's SplitCostModel with intersection_tests of each side's count
// (the same cost, to the bit, as split_cost). A plane on the cell's face with no triangle on its
// flat side is no candidate: it would give the other child the whole cell and every triangle. `cell` must have a positive surface area. Returns axis -1
// when there is no candidate; the plane's below_count and above_count are triangles, those in
// the plane counted on their side. Ties go to the first candidate in the order x, y, z, then by
// position, below before above.
SplitPlane find_split_plane(const NodeEvents& events, const Bounds3& cell, std::size_t triangle_count,
                            const KdTreeSettings& settings);

}  // namespace freezeray::ch06
