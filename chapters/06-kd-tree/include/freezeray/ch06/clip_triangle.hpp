// Clipping a triangle to a box: the bounds of the part of a triangle inside a cell, which the
// build uses for the triangles a split plane cuts ("perfect splits": Havran, "Heuristic Ray
// Shooting Algorithms", PhD thesis, 2000; Wald and Havran 2006, section 4.3).
#pragma once

#include "freezeray/math.hpp"

#include <optional>

namespace freezeray::ch06 {

// The bounds of triangle (p0, p1, p2) intersected with `box` (both closed sets), or nothing when
// they do not meet. The triangle is clipped as a polygon against the box's six planes in turn
// (Sutherland and Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974), in double precision;
// the bounds are rounded outward to floats, so that they contain the exact intersection, and lie
// within `box`. Coordinates that need no rounding (vertices, points on a plane) stay exact: a
// triangle lying in a plane of constant x keeps a box of zero extent in x.
std::optional<Bounds3> clip_triangle_to_box(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Bounds3& box);

}  // namespace freezeray::ch06
