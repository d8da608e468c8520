// Grading tests of chapter 06's exercises. Each test case is named after its exercise, calls the
// exercise's own function first (so that in a student copy it fails through its own stub), and
// checks it against exact values; clip-triangle also against an independent computation of the
// clipped polygon's vertices, near-far-order also by tracing rays through a tree against brute
// force, sah-sweep against every candidate plane counted triangle by triangle. Deterministic: no
// statistical test in this file.
#include "freezeray/ch06/clip_triangle.hpp"
#include "freezeray/ch06/kdtree_accelerator.hpp"
#include "freezeray/ch06/kdtree_traversal.hpp"
#include "freezeray/ch06/split_events.hpp"
#include "freezeray/ch06/split_plane_sweep.hpp"
#include "freezeray/ch06/surface_area_heuristic.hpp"
#include "freezeray/random.hpp"
#include "freezeray/ch01/warps.hpp"

#include "bias_detectors.hpp"
#include "test_bounds.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch06;
using freezeray::testing::box;

namespace {

// The bounds of triangle ∩ box from the vertices of that convex polygon, found without clipping:
// the triangle's vertices inside the box, its edges' crossings of the box's planes inside the box,
// and the box's edges' crossings of the triangle. Double precision, with a tolerance of `eps`.
std::optional<std::pair<glm::dvec3, glm::dvec3>> reference_clip(const glm::dvec3 v[3], const glm::dvec3& lo,
                                                                 const glm::dvec3& hi, double eps) {
    std::vector<glm::dvec3> points;
    auto in_box = [&](const glm::dvec3& p) {
        for (int k = 0; k < 3; ++k)
            if (p[k] < lo[k] - eps || p[k] > hi[k] + eps) return false;
        return true;
    };
    for (int i = 0; i < 3; ++i)
        if (in_box(v[i])) points.push_back(v[i]);
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 &a = v[i], &b = v[(i + 1) % 3];
        for (int k = 0; k < 3; ++k)
            for (double c : {lo[k], hi[k]})
                if ((a[k] - c) * (b[k] - c) < 0.0) {
                    const glm::dvec3 p = a + (b - a) * ((c - a[k]) / (b[k] - a[k]));
                    if (in_box(p)) points.push_back(p);
                }
    }
    const glm::dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
    for (int k = 0; k < 3; ++k)
        for (int corner = 0; corner < 4; ++corner) {
            glm::dvec3 q0 = lo, q1;
            q0[(k + 1) % 3] = (corner & 1) ? hi[(k + 1) % 3] : lo[(k + 1) % 3];
            q0[(k + 2) % 3] = (corner & 2) ? hi[(k + 2) % 3] : lo[(k + 2) % 3];
            q1 = q0;
            q1[k] = hi[k];
            const double denominator = glm::dot(n, q1 - q0);
            if (denominator == 0.0) continue;
            const double s = glm::dot(n, v[0] - q0) / denominator;
            if (s < 0.0 || s > 1.0) continue;
            const glm::dvec3 p = q0 + s * (q1 - q0);
            // Inside the triangle: the three edge normals agree with n.
            bool inside = true;
            for (int i = 0; i < 3; ++i)
                inside &= glm::dot(glm::cross(v[(i + 1) % 3] - v[i], p - v[i]), n) >= -eps * glm::dot(n, n);
            if (inside) points.push_back(p);
        }
    if (points.empty()) return std::nullopt;
    glm::dvec3 min = points[0], max = points[0];
    for (const glm::dvec3& p : points) min = glm::min(min, p), max = glm::max(max, p);
    return std::make_pair(min, max);
}

}  // namespace

namespace {

// One case of ch06/sah-cost: a cell split at a plane, the triangles on each side and the areas of
// the two children and of the cell (as the case's comment works them out).
struct SahCase {
    Bounds3 cell;
    int axis;
    float position;
    int below, above;
    double area_below, area_above, area_cell;
};

// The cost of a case by the formula of book chapter 06 (MacDonald and Booth 1990; Wald and Havran
// 2006, with the empty bonus), or with one classic mistake, so that a wrong answer can be named.
struct SahMistakes {
    bool no_area_division = false, bonus_as_factor = false, bonus_on_traversal = false, counts_swapped = false;
};
double sah_model(const KdTreeSettings& s, const SahCase& c, const SahMistakes& m = {}) {
    const double scale = m.no_area_division ? 1.0 : 1.0 / c.area_cell;
    const double below = m.counts_swapped ? c.above : c.below, above = m.counts_swapped ? c.below : c.above;
    const double bonus = (c.below == 0 || c.above == 0) ? s.empty_bonus : 0.0;
    const double factor = m.bonus_as_factor && bonus > 0.0 ? bonus : 1.0 - bonus;
    const double intersections = s.intersection_cost * scale * (c.area_below * below + c.area_above * above);
    return m.bonus_on_traversal ? factor * (s.traversal_cost + intersections) : s.traversal_cost + factor * intersections;
}

// Checks one case; on failure says which case, what was expected and what came, and names the
// classic mistake the answer matches, if one does.
void check_sah(const KdTreeSettings& s, const SahCase& c, double epsilon = 1e-12) {
    const double expected = sah_model(s, c);
    const double got = split_cost(s, c.cell, c.axis, c.position, static_cast<std::size_t>(c.below),
                                  static_cast<std::size_t>(c.above));
    std::vector<testing::Suspect> suspects;
    auto suspect = [&](const std::string& mistake, const SahMistakes& m) {
        const double predicted = sah_model(s, c, m);
        if (std::abs(predicted - expected) > 1e-9 * std::abs(expected)) suspects.push_back({mistake, predicted});
    };
    suspect("the children's areas are not divided by the cell's: the probability that a ray through the cell "
            "meets a child is SA(child) / SA(cell)", {.no_area_division = true});
    suspect("the empty bonus multiplies the intersection cost; it takes its share off: (1 - bonus)",
            {.bonus_as_factor = true});
    suspect("the empty bonus also scales the traversal cost; it applies to the intersection term only",
            {.bonus_on_traversal = true});
    suspect("the counts are swapped: the triangles below go with the area below", {.counts_swapped = true});
    INFO("split on axis " << c.axis << " at " << c.position << ", " << c.below << " triangles below and " << c.above
                          << " above: expected " << expected << ", got " << got);
    INFO(testing::likely_mistake(got, suspects, 1e-6));
    CHECK(got == Approx(expected).epsilon(epsilon));
}

}  // namespace

TEST_CASE("ch06/sah-cost", "[exercise]") {
    KdTreeSettings s;  // the costs are set here, whatever the defaults are
    s.traversal_cost = 15.0f;
    s.intersection_cost = 20.0f;
    s.empty_bonus = 0.25f;
    const Bounds3 cube = box(Vec3(0.0f), Vec3(1.0f));  // surface area 6
    // Halves: each child has area 4 of 6.
    check_sah(s, {cube, 0, 0.5f, 3, 5, 4.0, 4.0, 6.0});
    check_sah(s, {cube, 1, 0.5f, 3, 5, 4.0, 4.0, 6.0});
    // At 0.25 along z: areas 2 (0.25 + 0.25 + 1) = 3 and 2 (0.75 + 0.75 + 1) = 5.
    check_sah(s, {cube, 2, 0.25f, 4, 2, 3.0, 5.0, 6.0});
    // One child empty: the bonus takes a quarter of the intersection cost off.
    check_sah(s, {cube, 0, 0.25f, 0, 4, 3.0, 5.0, 6.0});
    check_sah(s, {cube, 0, 0.75f, 4, 0, 5.0, 3.0, 6.0});
    // A plane on the cell's face: the flat child still has the area of its two faces, 2 of 6.
    check_sah(s, {cube, 0, 0.0f, 2, 5, 2.0, 6.0, 6.0});
    // A flat cell 2 x 1 x 0 (area 4): split at x = 0.5 into areas 1 and 3.
    check_sah(s, {box(Vec3(0.0f), Vec3(2.0f, 1.0f, 0.0f)), 0, 0.5f, 2, 2, 1.0, 3.0, 4.0});
    // Other costs, and a box far from the origin (areas, not coordinates, matter).
    s.traversal_cost = 1.0f;
    s.intersection_cost = 80.0f;
    s.empty_bonus = 0.5f;
    const Bounds3 far = box(Vec3(1000.0f, -3000.0f, 50.0f), Vec3(1004.0f, -2998.0f, 51.0f));  // 4 x 2 x 1, area 28
    // x = 1001: below 1 x 2 x 1 (area 10), above 3 x 2 x 1 (area 22).
    check_sah(s, {far, 0, 1001.0f, 7, 9, 10.0, 22.0, 28.0});
    check_sah(s, {far, 0, 1001.0f, 0, 9, 10.0, 22.0, 28.0});
    // A huge cell: no overflow (children of area 16e60 in a cell of 24e60).
    check_sah(s, {box(Vec3(-1e30f), Vec3(1e30f)), 1, 0.0f, 1, 1, 16e60, 16e60, 24e60}, 1e-6);
}

namespace {

// The cheapest plane found without a sweep: at every event position of every axis the cell is
// not flat along, the triangles below, in and above the plane counted box by box, in the order
// and with the rules that find_split_plane's comment states (O(N^2), for small nodes only).
SplitPlane every_candidate(const std::vector<Bounds3>& boxes, const Bounds3& cell, const KdTreeSettings& settings) {
    SplitPlane best;
    best.cost = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (cell.min[axis] == cell.max[axis]) continue;
        std::vector<float> positions;
        for (const Bounds3& b : boxes) {
            positions.push_back(b.min[axis]);
            positions.push_back(b.max[axis]);
        }
        std::sort(positions.begin(), positions.end());
        positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
        for (const float p : positions) {
            std::size_t below = 0, in = 0, above = 0;
            for (const Bounds3& b : boxes) {
                if (b.min[axis] == b.max[axis]) {
                    below += b.min[axis] < p;
                    in += b.min[axis] == p;
                    above += b.min[axis] > p;
                } else {
                    below += b.min[axis] < p;
                    above += b.max[axis] > p;
                }
            }
            auto consider = [&](std::size_t n_below, std::size_t n_above, bool planar_below) {
                if (p == cell.min[axis] && n_below == 0) return;
                if (p == cell.max[axis] && n_above == 0) return;
                const double cost = split_cost(settings, cell, axis, p, intersection_tests(settings, n_below),
                                               intersection_tests(settings, n_above));
                if (cost < best.cost) best = SplitPlane{axis, p, planar_below, cost, n_below, n_above};
            };
            consider(below + in, above, true);
            if (in > 0) consider(below, above + in, false);
        }
    }
    return best;
}

SplitPlane sweep(const std::vector<Bounds3>& boxes, const Bounds3& cell, const KdTreeSettings& settings) {
    NodeEvents events;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) add_triangle_events(events, i, boxes[i]);
    sort_events(events);
    return find_split_plane(events, cell, boxes.size(), settings);
}

std::string describe(const SplitPlane& p) {
    return "axis " + std::to_string(p.axis) + " at " + std::to_string(p.position) + (p.planar_below ? " (in-plane below)" : " (in-plane above)") +
           ", cost " + std::to_string(p.cost) + ", " + std::to_string(p.below_count) + " below, " + std::to_string(p.above_count) + " above";
}

bool same_plane(const SplitPlane& a, const SplitPlane& b) {
    if (a.axis != b.axis) return false;
    if (a.axis < 0) return true;
    return a.position == b.position && a.planar_below == b.planar_below && a.cost == b.cost &&
           a.below_count == b.below_count && a.above_count == b.above_count;
}

}  // namespace

TEST_CASE("ch06/sah-sweep", "[exercise]") {
    KdTreeSettings settings;  // set here, whatever the defaults are
    settings.traversal_cost = 1.0f;
    settings.intersection_cost = 80.0f;
    settings.empty_bonus = 0.5f;
    const Bounds3 cell = box(Vec3(0.0f), Vec3(4.0f));

    // Two clusters apart along y: the plane goes between them, at the end of the lower one.
    const std::vector<Bounds3> apart{box(Vec3(0.0f), Vec3(4.0f, 1.0f, 4.0f)), box(Vec3(0.0f, 0.5f, 0.0f), Vec3(4.0f, 1.0f, 4.0f)),
                                     box(Vec3(0.0f, 3.0f, 0.0f), Vec3(4.0f)), box(Vec3(0.0f, 3.5f, 0.0f), Vec3(4.0f))};
    const SplitPlane split = sweep(apart, cell, settings);
    INFO("found " << describe(split) << "; expected " << describe(every_candidate(apart, cell, settings)));
    REQUIRE(split.axis == 1);
    CHECK(split.position == 1.0f);
    CHECK(split.below_count == 2);
    CHECK(split.above_count == 2);
    CHECK(same_plane(split, every_candidate(apart, cell, settings)));

    // One triangle filling the cell: no plane separates anything.
    CHECK(sweep({cell}, cell, settings).axis == -1);

    // A floor lying in z = 0 under a box: the floor goes below a plane at z = 0 only if that pays.
    const std::vector<Bounds3> floor_and_box{box(Vec3(0.0f), Vec3(4.0f, 4.0f, 0.0f)), box(Vec3(1.0f, 1.0f, 2.0f), Vec3(3.0f))};
    CHECK(same_plane(sweep(floor_and_box, cell, settings), every_candidate(floor_and_box, cell, settings)));

    // Random nodes: boxes on a coarse grid, so that positions are shared and many boxes are flat
    // (triangles lying in planes), in cells flat along one axis too, costed per triangle and per
    // packet of 4, with and without the bonus.
    PCG32 random(61, 6);
    int compared = 0, above_choices = 0;
    for (int node = 0; node < 400; ++node) {
        const bool flat_cell = node % 5 == 4;
        const int flat_axis = node % 3;
        Bounds3 node_cell = cell;
        if (flat_cell) node_cell.max[flat_axis] = node_cell.min[flat_axis] = 2.0f;
        KdTreeSettings s = settings;
        s.triangles_per_test = node % 2 == 0 ? 1 : 4;
        s.empty_bonus = node % 3 == 0 ? 0.0f : 0.5f;
        s.intersection_cost = node % 4 == 0 ? 2.0f : 80.0f;
        std::vector<Bounds3> boxes;
        const std::uint32_t count = 1 + random.next_below(30);
        for (std::uint32_t i = 0; i < count; ++i) {
            Bounds3 b;
            for (int k = 0; k < 2; ++k)
                b.expand(Vec3(0.5f * static_cast<float>(random.next_below(9)), 0.5f * static_cast<float>(random.next_below(9)),
                              0.5f * static_cast<float>(random.next_below(9))));
            if (random.next_below(3) == 0) {  // flat along a random axis
                const int a = static_cast<int>(random.next_below(3));
                b.max[a] = b.min[a];
            }
            if (flat_cell) b.min[flat_axis] = b.max[flat_axis] = 2.0f;
            boxes.push_back(b);
        }
        const SplitPlane found = sweep(boxes, node_cell, s);
        const SplitPlane expected = every_candidate(boxes, node_cell, s);
        INFO("node " << node << " of " << count << " triangles: found " << describe(found) << "; expected " << describe(expected));
        REQUIRE(same_plane(found, expected));
        CHECK((!flat_cell || found.axis != flat_axis));
        ++compared;
        above_choices += found.axis >= 0 && !found.planar_below;
    }
    CHECK(compared == 400);
    CHECK(above_choices > 0);  // the cases reached the choice of putting in-plane triangles above
}

TEST_CASE("ch06/clip-triangle", "[exercise]") {
    const Bounds3 unit = box(Vec3(0.0f), Vec3(1.0f));
    // Inside: its own bounds, exactly.
    const auto inside = clip_triangle_to_box(Vec3(0.1f, 0.2f, 0.3f), Vec3(0.9f, 0.25f, 0.4f), Vec3(0.5f, 0.8f, 0.7f), unit);
    REQUIRE(inside);
    CHECK(inside->min == Vec3(0.1f, 0.2f, 0.3f));
    CHECK(inside->max == Vec3(0.9f, 0.8f, 0.7f));
    // Outside: nothing.
    CHECK_FALSE(clip_triangle_to_box(Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0), unit));
    CHECK_FALSE(clip_triangle_to_box(Vec3(0.8f, 1.5f, 0.5f), Vec3(1.5f, 0.8f, 0.5f), Vec3(1.5f, 1.5f, 0.5f), unit));
    // A triangle whose bounding box overlaps the box but which does not: nothing either.
    CHECK_FALSE(clip_triangle_to_box(Vec3(0.9f, 2, 0.5f), Vec3(2, 0.9f, 0.5f), Vec3(2, 2, 0.5f), unit));
    // Cut by two planes: the square [0, 1]^2 of the plane z = 0, flat in z exactly.
    const auto square = clip_triangle_to_box(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), box(Vec3(0, 0, -1), Vec3(1, 1, 1)));
    REQUIRE(square);
    CHECK(square->min == Vec3(0, 0, 0));
    CHECK(square->max == Vec3(1, 1, 0));
    // The hypotenuse x + y = 3 cuts the box [1, 3]^2 to the triangle (1, 1), (2, 1), (1, 2).
    const auto corner = clip_triangle_to_box(Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(0, 3, 0), box(Vec3(1, 1, -1), Vec3(3, 3, 1)));
    REQUIRE(corner);
    CHECK(corner->min == Vec3(1, 1, 0));
    CHECK(corner->max == Vec3(2, 2, 0));
    // A tilted triangle in z = x + y, cut by z <= 0.5: x, y and z in [0, 0.5].
    const auto tilted = clip_triangle_to_box(Vec3(0, 0, 0), Vec3(1, 0, 1), Vec3(0, 1, 1), box(Vec3(0, 0, 0), Vec3(1, 1, 0.5f)));
    REQUIRE(tilted);
    CHECK(tilted->min == Vec3(0, 0, 0));
    CHECK(tilted->max == Vec3(0.5f, 0.5f, 0.5f));
    // Touching the box at one vertex only: that point (a triangle touching a cell is not lost).
    const auto touching = clip_triangle_to_box(Vec3(1, 0.5f, 0.5f), Vec3(2, 0.5f, 0.5f), Vec3(2, 1, 0.5f), unit);
    REQUIRE(touching);
    CHECK(touching->min == Vec3(1, 0.5f, 0.5f));
    CHECK(touching->max == Vec3(1, 0.5f, 0.5f));

    // Random triangles and boxes against the polygon's vertices found independently: the result
    // contains the exact bounds, lies within the box, and is tight to within 1e-6 of the scene.
    PCG32 random(6, 6);
    auto point = [&](float scale) { return scale * Vec3(random.next_float(), random.next_float(), random.next_float()); };
    int checked = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 p[3] = {point(4.0f) - Vec3(1.0f), point(4.0f) - Vec3(1.0f), point(4.0f) - Vec3(1.0f)};
        const Bounds3 cell = box(point(2.0f), point(2.0f));
        const auto clipped = clip_triangle_to_box(p[0], p[1], p[2], cell);
        const glm::dvec3 v[3] = {glm::dvec3(p[0]), glm::dvec3(p[1]), glm::dvec3(p[2])};
        const auto expected = reference_clip(v, glm::dvec3(cell.min), glm::dvec3(cell.max), 1e-12);
        INFO("triangle " << i);
        REQUIRE(clipped.has_value() == expected.has_value());
        if (!clipped) continue;
        ++checked;
        for (int k = 0; k < 3; ++k) {
            CHECK(clipped->min[k] >= cell.min[k]);
            CHECK(clipped->max[k] <= cell.max[k]);
            CHECK(static_cast<double>(clipped->min[k]) <= expected->first[k] + 1e-12);
            CHECK(static_cast<double>(clipped->max[k]) >= expected->second[k] - 1e-12);
            CHECK(static_cast<double>(clipped->min[k]) >= expected->first[k] - 1e-6);
            CHECK(static_cast<double>(clipped->max[k]) <= expected->second[k] + 1e-6);
        }
    }
    CHECK(checked > 500);
}

TEST_CASE("ch06/near-far-order", "[exercise]") {
    // A node splitting x at 1, its own index 3 (so its below child is 4), its above child 7.
    const KdTreeNode node = KdTreeNode::interior(0, 1.0f, 7);
    auto order = [&](const Vec3& origin, const Vec3& direction) {
        const Ray ray{origin, direction};
        return order_children(node, 3, ray, 1.0f / direction);
    };
    const ChildOrder forward = order(Vec3(0, 5, 5), Vec3(1, 0, 0));
    REQUIRE(forward.near_child == 4);
    CHECK(forward.far_child == 7);
    CHECK(forward.t_plane == 1.0f);
    const ChildOrder backward = order(Vec3(3, 0, 0), Vec3(-0.5f, 0.5f, 0));
    CHECK(backward.near_child == 7);
    CHECK(backward.far_child == 4);
    CHECK(backward.t_plane == 4.0f);
    // Going away from the plane: the plane lies behind (t < 0), the first child is the one the
    // ray's line has left, the one the ray is in is second.
    const ChildOrder away = order(Vec3(0.5f, 0, 0), Vec3(-1, 0, 0));
    CHECK(away.near_child == 7);
    CHECK(away.far_child == 4);
    CHECK(away.t_plane < 0.0f);
    // From the plane: the order of the direction; lying in the plane, below first.
    CHECK(order(Vec3(1, 0, 0), Vec3(1, 0, 0)).near_child == 4);
    CHECK(order(Vec3(1, 0, 0), Vec3(-1, 0, 0)).near_child == 7);
    const ChildOrder in_plane = order(Vec3(1, 0, 0), Vec3(0, 1, 0));
    CHECK(in_plane.near_child == 4);
    CHECK(std::isnan(in_plane.t_plane));
    // Parallel to the plane, off it: the origin's side first, the plane never reached.
    const ChildOrder parallel = order(Vec3(2, 0, 0), Vec3(0, 0, 1));
    CHECK(parallel.near_child == 7);
    CHECK(std::isinf(parallel.t_plane));
    // The other axes.
    const KdTreeNode y_node = KdTreeNode::interior(1, -2.0f, 9), z_node = KdTreeNode::interior(2, 0.0f, 2);
    const Ray up{Vec3(0, -3, 0), glm::normalize(Vec3(0, 1, 1))};
    CHECK(order_children(y_node, 0, up, 1.0f / up.direction).near_child == 1);
    const Ray down{Vec3(0, 0, 1), Vec3(0, 0, -1)};
    const ChildOrder z = order_children(z_node, 0, down, 1.0f / down.direction);
    CHECK(z.near_child == 2);
    CHECK(z.far_child == 1);
    CHECK(z.t_plane == 1.0f);

    // Through a whole tree: front to back, the closest hit is found first and the walk stops
    // after it. In the wrong order, farther triangles would be reported.
    TriangleMesh soup;
    PCG32 random(8, 8);
    for (std::uint32_t i = 0; i < 500; ++i) {
        const Vec3 centre(random.next_float(), random.next_float(), random.next_float());
        for (int k = 0; k < 3; ++k)
            soup.positions.push_back(centre + 0.3f * Vec3(random.next_float() - 0.5f, random.next_float() - 0.5f, random.next_float() - 0.5f));
        soup.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    soup.face_materials.assign(soup.triangles.size(), 0u);
    const std::vector<TriangleMesh> meshes{soup};
    BruteForceAccelerator brute_force;
    KdTreeAccelerator tree;
    brute_force.build(meshes);
    tree.build(meshes);
    int differing = 0, hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 origin = Vec3(-0.5f) + 2.0f * Vec3(random.next_float(), random.next_float(), random.next_float());
        const Ray ray{origin, ch01::sample_uniform_sphere(Vec2(random.next_float(), random.next_float()))};
        const auto expected = brute_force.intersect(ray);
        const auto found = tree.intersect(ray);
        hits += expected ? 1 : 0;
        const bool same = expected ? found && found->triangle == expected->triangle &&
                                         std::bit_cast<std::uint32_t>(found->t) == std::bit_cast<std::uint32_t>(expected->t)
                                   : !found;
        differing += same ? 0 : 1;
    }
    CHECK(hits > 3000);
    CHECK(differing == 0);
}
