// Events per axis, and dividing a node's events between its children in linear time (Wald and
// Havran 2006, section 4.3).
#include "freezeray/ch06/split_events.hpp"

#include "freezeray/ch06/clip_triangle.hpp"

#include <algorithm>
#include <bit>
#include <utility>

namespace freezeray::ch06 {

void add_triangle_events(NodeEvents& events, std::uint32_t triangle, const Bounds3& box) {
    for (int axis = 0; axis < 3; ++axis) {
        auto& list = events[static_cast<std::size_t>(axis)];
        if (box.min[axis] == box.max[axis]) {
            list.push_back({box.min[axis], triangle, EventType::Planar});
        } else {
            list.push_back({box.min[axis], triangle, EventType::Start});
            list.push_back({box.max[axis], triangle, EventType::End});
        }
    }
}

void sort_events(NodeEvents& events) {
    for (auto& list : events) std::sort(list.begin(), list.end());
}

namespace {

// An event's position and type as one unsigned number in the order of operator<: the float's
// bits with the sign bit flipped for positives and all bits flipped for negatives (so that
// unsigned order is numeric order), -0 counted as +0 (they compare equal), the type below them.
std::uint64_t sort_key(const SplitEvent& e) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(e.position + 0.0f);  // -0 + 0 is +0
    const std::uint32_t ordered = (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
    return (std::uint64_t{ordered} << 2) | static_cast<std::uint64_t>(e.type);
}

}  // namespace

// Least significant digit first, each pass a stable counting sort on the next 12 of the key's
// 34 bits: after the last pass the list is in key order, equal keys in the order they came.
void sort_events_added_in_triangle_order(std::vector<SplitEvent>& list) {
    constexpr int DigitBits = 12, KeyBits = 34;
    constexpr std::size_t Digits = std::size_t{1} << DigitBits;
    const std::size_t n = list.size();
    std::vector<std::uint64_t> keys(n), next_keys(n);
    std::vector<SplitEvent> next(n);
    for (std::size_t i = 0; i < n; ++i) keys[i] = sort_key(list[i]);
    std::vector<std::size_t> start(Digits);
    for (int shift = 0; shift < KeyBits; shift += DigitBits) {
        auto digit = [shift](std::uint64_t key) { return static_cast<std::size_t>(key >> shift) & (Digits - 1); };
        std::fill(start.begin(), start.end(), 0);
        for (const std::uint64_t key : keys) ++start[digit(key)];
        std::size_t sum = 0;
        for (std::size_t& s : start) sum += std::exchange(s, sum);  // counts to where each digit starts
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t to = start[digit(keys[i])]++;
            next[to] = list[i];
            next_keys[to] = keys[i];
        }
        list.swap(next);
        keys.swap(next_keys);
    }
}

std::vector<std::uint32_t> triangles_of(const NodeEvents& events) {
    std::vector<std::uint32_t> triangles;
    for (const SplitEvent& e : events[0])
        if (e.type != EventType::End) triangles.push_back(e.triangle);
    std::sort(triangles.begin(), triangles.end());
    return triangles;
}

namespace {

// BOOK(classify-triangles)
// The classification of Wald and Havran 2006, section 4.3: a triangle is below the plane if its box ends at or
// before it, above if it starts at or after it, both if the plane cuts its box; a triangle lying
// in the plane goes to the side the cost model chose. One pass: a triangle's Start event comes
// before its End event (its box is not flat along the axis, so it starts before it ends), and
// the End event corrects what the Start event set when the box ends at or before the plane.
void classify_triangles(const std::vector<SplitEvent>& axis_events, const SplitPlane& plane, std::vector<Side>& sides) {
    for (const SplitEvent& e : axis_events) {
        if (e.type == EventType::Start) {
            sides[e.triangle] = e.position >= plane.position ? Side::Above : Side::Both;
        } else if (e.type == EventType::End) {
            if (e.position <= plane.position) sides[e.triangle] = Side::Below;
        } else {  // Planar
            const bool below = e.position < plane.position || (e.position == plane.position && plane.planar_below);
            sides[e.triangle] = below ? Side::Below : Side::Above;
        }
    }
}
// END BOOK

// The cut triangle's box within a child cell. The exact intersection is never empty (the box
// the plane cuts is that of the triangle's part inside the node, so that part has points on
// both sides); should rounding make it so, the whole child cell is a box that surely holds it.
Bounds3 box_within(const TriangleVertices& t, const Bounds3& child_cell) {
    const auto box = clip_triangle_to_box(t.p0, t.p1, t.p2, child_cell);
    return box ? *box : child_cell;
}

// Merges the sorted `cut` into the sorted `kept`, in linear time (Wald and Havran 2006, section
// 4.3) and in place: from the back, so that no event is overwritten before it has moved.
void merge_sorted_into(std::vector<SplitEvent>& kept, const std::vector<SplitEvent>& cut) {
    if (cut.empty()) return;
    std::size_t from_kept = kept.size(), from_cut = cut.size();
    kept.resize(kept.size() + cut.size());
    for (std::size_t to = kept.size(); from_cut > 0;) {
        if (from_kept > 0 && cut[from_cut - 1] < kept[from_kept - 1])
            kept[--to] = kept[--from_kept];
        else
            kept[--to] = cut[--from_cut];
    }
}

}  // namespace

ChildEvents split_events(const NodeEvents& events, const SplitPlane& plane, const Bounds3& cell,
                         const std::vector<TriangleVertices>& triangles, std::vector<Side>& sides) {
    const auto& axis_events = events[static_cast<std::size_t>(plane.axis)];
    classify_triangles(axis_events, plane, sides);

    ChildEvents children;
    std::size_t cut_count = 0;
    for (const SplitEvent& e : axis_events) {
        if (e.type == EventType::End) continue;  // count each triangle once
        const Side side = sides[e.triangle];
        if (side == Side::Below) ++children.below_count;
        else if (side == Side::Above) ++children.above_count;
        else ++cut_count;
    }

    const std::size_t below_only = children.below_count, above_only = children.above_count;

    // BOOK(cut-triangles)
    // Triangles the plane cuts: clipped to each child's cell, their new events sorted apart.
    Bounds3 below_cell = cell, above_cell = cell;
    below_cell.max[plane.axis] = plane.position;
    above_cell.min[plane.axis] = plane.position;
    NodeEvents cut_below, cut_above;
    for (std::size_t axis = 0; axis < 3; ++axis) {  // at most two events per triangle and axis
        cut_below[axis].reserve(2 * cut_count);
        cut_above[axis].reserve(2 * cut_count);
    }
    for (const SplitEvent& e : axis_events) {
        if (e.type != EventType::Start || sides[e.triangle] != Side::Both) continue;
        const TriangleVertices& t = triangles[e.triangle];
        add_triangle_events(cut_below, e.triangle, box_within(t, below_cell));
        add_triangle_events(cut_above, e.triangle, box_within(t, above_cell));
        ++children.below_count;
        ++children.above_count;
    }
    sort_events(cut_below);
    sort_events(cut_above);
    // END BOOK

    for (std::size_t axis = 0; axis < 3; ++axis) {
        // Triangles on one side keep their events, in order (each list reserved for two events
        // per triangle kept, at most, and the cut ones' events).
        auto& below = children.below[axis];
        auto& above = children.above[axis];
        below.reserve(2 * below_only + cut_below[axis].size());
        above.reserve(2 * above_only + cut_above[axis].size());
        for (const SplitEvent& e : events[axis]) {
            const Side side = sides[e.triangle];
            if (side == Side::Below) below.push_back(e);
            else if (side == Side::Above) above.push_back(e);
        }
        merge_sorted_into(below, cut_below[axis]);
        merge_sorted_into(above, cut_above[axis]);
    }
    return children;
}

}  // namespace freezeray::ch06
