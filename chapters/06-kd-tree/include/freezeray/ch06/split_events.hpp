// The events of the O(N log N) build (Wald and Havran, "On building fast kd-Trees for Ray
// Tracing, and on doing that in O(N log N)", 2006, section 4): where a triangle's box begins and
// ends along each axis, kept sorted per axis for the whole build, and how a node's events are
// divided between its two children without sorting again (section 4.3).
#pragma once

#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/math.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace freezeray::ch06 {

// BOOK(split-event-order)
// At equal positions ends come first, then planar triangles, then starts, so that a sweep over
// the events counts, at each candidate plane, the triangles below it before those above it.
enum class EventType : std::uint8_t { End = 0, Planar = 1, Start = 2 };

struct SplitEvent {
    float position;
    std::uint32_t triangle;  // the triangle's global index
    EventType type;
};

// The order of Wald and Havran 2006: by position, then type; the triangle index last makes the
// order total, so that every build of a scene gives the same tree.
inline bool operator<(const SplitEvent& a, const SplitEvent& b) {
    if (a.position != b.position) return a.position < b.position;
    if (a.type != b.type) return a.type < b.type;
    return a.triangle < b.triangle;
}
// END BOOK

// A node's events, one sorted list per axis. Every triangle of the node has on each axis either
// one Start and one End event or, when its box is flat along that axis, one Planar event.
using NodeEvents = std::array<std::vector<SplitEvent>, 3>;

// Appends the events of a triangle whose box (within the node's cell) is `box`; unsorted.
void add_triangle_events(NodeEvents& events, std::uint32_t triangle, const Bounds3& box);

// Sorts each axis's list.
void sort_events(NodeEvents& events);

// The same order, for one axis's list of events added in increasing triangle order, as the
// build adds the root's: a stable radix sort on position and type (Knuth, The Art of Computer
// Programming, vol. 3, section 5.2.5), which leaves events of equal position and type in
// triangle order. Linear in the events: the root's million events of Crytek Sponza sort in a
// sixth of sort_events's time.
void sort_events_added_in_triangle_order(std::vector<SplitEvent>& axis_events);

// The triangles of a node, in increasing order (each triangle's one Start or Planar event on x).
std::vector<std::uint32_t> triangles_of(const NodeEvents& events);

// Which side of a split plane a triangle goes to.
enum class Side : std::uint8_t { Below, Above, Both };

// A chosen split: the plane, and which side takes the triangles lying in it.
struct SplitPlane {
    int axis = -1;  // -1: no split found
    float position = 0.0f;
    bool planar_below = true;
    double cost = 0.0;
    std::size_t below_count = 0;  // triangles of each child, those in the plane included
    std::size_t above_count = 0;
};

// The events of a node's two children (Wald and Havran 2006, section 4.3). Triangles
// entirely on one side keep their events, so those lists stay sorted; a triangle the plane cuts is
// clipped to each child's cell (perfect splits) and its new events, sorted apart, are merged in:
// linear time apart from sorting the new events of the few cut triangles. `sides` is scratch
// space with one entry per global triangle.
struct ChildEvents {
    NodeEvents below, above;
    std::size_t below_count = 0, above_count = 0;
};
ChildEvents split_events(const NodeEvents& events, const SplitPlane& plane, const Bounds3& cell,
                         const std::vector<TriangleVertices>& triangles, std::vector<Side>& sides);

}  // namespace freezeray::ch06
