// The sweep of Wald and Havran 2006, section 4.3: at every event position p, the counts of the
// triangles below, in and above the plane follow from the events met so far.
#include "freezeray/ch06/split_plane_sweep.hpp"

#include "freezeray/ch06/surface_area_heuristic.hpp"

#include <limits>

namespace freezeray::ch06 {

// BOOK(split-plane-sweep)
SplitPlane find_split_plane(const NodeEvents& events, const Bounds3& cell, std::size_t triangle_count,
                            const KdTreeSettings& settings) {
    // EXERCISE(ch06/sah-sweep): the sweep of book chapter 06, "The sweep", as find_split_plane's comment in split_plane_sweep.hpp states it: every plane through an event on each axis the cell is not flat along, its counts below, in and above it from the events met so far, both sides for the triangles lying in it, costed with SplitCostModel::cost; the cheapest, first found on ties
    const SplitCostModel costs(settings, cell);
    SplitPlane best;
    best.cost = std::numeric_limits<double>::infinity();
    auto consider = [&](int axis, float position, std::size_t below, std::size_t above, bool planar_below) {
        // A plane on the cell's face whose flat child would be empty leaves the other child the
        // whole cell and every triangle: no progress (and the empty bonus would repeat forever).
        if (position == cell.min[axis] && below == 0) return;
        if (position == cell.max[axis] && above == 0) return;
        const double cost = costs.cost(axis, position, intersection_tests(settings, below), intersection_tests(settings, above));
        if (cost < best.cost) best = SplitPlane{axis, position, planar_below, cost, below, above};
    };

    for (int axis = 0; axis < 3; ++axis) {
        if (cell.min[axis] == cell.max[axis]) continue;  // a flat cell cannot be split along its flat axis
        const auto& list = events[static_cast<std::size_t>(axis)];
        std::size_t below = 0, planar = 0, above = triangle_count;
        for (std::size_t i = 0; i < list.size();) {
            const float p = list[i].position;
            std::size_t ending = 0, lying = 0, starting = 0;
            while (i < list.size() && list[i].position == p && list[i].type == EventType::End) ++ending, ++i;
            while (i < list.size() && list[i].position == p && list[i].type == EventType::Planar) ++lying, ++i;
            while (i < list.size() && list[i].position == p && list[i].type == EventType::Start) ++starting, ++i;
            // Triangles ending at p and lying in p are no longer above the plane through p.
            planar = lying;
            above -= lying + ending;
            consider(axis, p, below + planar, above, true);
            if (planar > 0) consider(axis, p, below, above + planar, false);
            // Past p, those lying in it and those starting at it are below.
            below += starting + planar;
        }
    }
    return best;
    // END EXERCISE
}
// END BOOK

}  // namespace freezeray::ch06
