// Sutherland-Hodgman clipping of a triangle against a box (Sutherland and Hodgman, "Reentrant
// polygon clipping", CACM 17(1), 1974), as kd-tree builders with perfect splits use it (Havran,
// "Heuristic Ray Shooting Algorithms", 2000; Wald and Havran 2006, section 4.3).
#include "freezeray/ch06/clip_triangle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace freezeray::ch06 {

namespace {

// A convex polygon: a triangle cut by six planes has at most 3 + 6 vertices (each plane removes
// at least one vertex for the two it adds, or leaves the polygon as it is).
struct ClipPolygon {
    std::array<glm::dvec3, 9> vertices;
    int count = 0;
    void add(const glm::dvec3& v) { vertices[static_cast<std::size_t>(count++)] = v; }
    glm::dvec3& add() { return vertices[static_cast<std::size_t>(count++)]; }
};

// BOOK(clip-helpers)
// The largest float not above x, and the smallest not below: float(x) when x is a float.
float float_below(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}

float float_above(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

// The point where segment a-b crosses the plane coordinate[axis] = value (a and b on opposite
// sides), written to p: exactly on the plane, and never outside the segment's own bounds.
void crossing_point(const glm::dvec3& a, const glm::dvec3& b, int axis, double value, glm::dvec3& p) {
    const double s = (value - a[axis]) / (b[axis] - a[axis]);
    for (int k = 0; k < 3; ++k) p[k] = std::clamp(a[k] + (b[k] - a[k]) * s, std::min(a[k], b[k]), std::max(a[k], b[k]));
    p[axis] = value;
}
// END BOOK

}  // namespace

// BOOK(clip-triangle-to-box)
std::optional<Bounds3> clip_triangle_to_box(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Bounds3& box) {
    // EXERCISE(ch06/clip-triangle): clip the triangle against the box as book chapter 06, "Perfect splits", describes it (Sutherland–Hodgman, points on a plane kept), and return the bounds of what is left, rounded outward to floats and within the box, or nothing when nothing is left
    // Two polygons in turn: each plane that cuts clips one into the other, nothing copied.
    std::array<ClipPolygon, 2> polygons;
    ClipPolygon* polygon = &polygons[0];
    ClipPolygon* clipped = &polygons[1];
    polygon->add(glm::dvec3(p0));
    polygon->add(glm::dvec3(p1));
    polygon->add(glm::dvec3(p2));
    for (int plane = 0; plane < 6 && polygon->count > 0; ++plane) {
        const int axis = plane / 2;
        const bool keep_above = plane % 2 == 0;  // min planes keep what is above them
        const double value = keep_above ? box.min[axis] : box.max[axis];
        auto inside = [&](const glm::dvec3& v) { return keep_above ? v[axis] >= value : v[axis] <= value; };
        int inside_count = 0;
        for (int i = 0; i < polygon->count; ++i) inside_count += inside(polygon->vertices[static_cast<std::size_t>(i)]);
        if (inside_count == polygon->count) continue;  // the plane cuts nothing off
        clipped->count = 0;
        for (int i = 0; i < polygon->count; ++i) {
            const glm::dvec3& a = polygon->vertices[static_cast<std::size_t>(i)];
            const glm::dvec3& b = polygon->vertices[static_cast<std::size_t>(i + 1 < polygon->count ? i + 1 : 0)];
            const bool a_inside = inside(a), b_inside = inside(b);
            if (a_inside) clipped->add(a);
            if (a_inside != b_inside) crossing_point(a, b, axis, value, clipped->add());
        }
        std::swap(polygon, clipped);
    }
    if (polygon->count == 0) return std::nullopt;

    glm::dvec3 low = polygon->vertices[0], high = polygon->vertices[0];
    for (int i = 1; i < polygon->count; ++i) {
        low = glm::min(low, polygon->vertices[static_cast<std::size_t>(i)]);
        high = glm::max(high, polygon->vertices[static_cast<std::size_t>(i)]);
    }
    Bounds3 bounds;
    for (int k = 0; k < 3; ++k) {
        bounds.min[k] = std::max(float_below(low[k]), box.min[k]);
        bounds.max[k] = std::min(float_above(high[k]), box.max[k]);
    }
    return bounds;
    // END EXERCISE
}
// END BOOK

}  // namespace freezeray::ch06
