// The KD-tree's build: degenerate input, determinism, the cells of its leaves, perfect splits,
// its statistics and settings; rays it must refuse.
#include "kdtree_test_support.hpp"
#include "test_bounds.hpp"
#include "test_scenes.hpp"

#include "freezeray/ch06/kdtree_accelerator.hpp"
#include "freezeray/ch06/kdtree_builder.hpp"
#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/ch06/split_events.hpp"
#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/ch03/register_chapter03.hpp"
#include "freezeray/ch04/register_chapter04.hpp"
#include "freezeray/ch05/register_chapter05.hpp"
#include "freezeray/error.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

using namespace freezeray;
using namespace freezeray::testing;
using ch06::KdTree;
using ch06::KdTreeAccelerator;
using ch06::KdTreeNode;

namespace {

void check_conformance(const std::vector<TriangleMesh>& meshes, const Bounds3& origins, int count, std::uint64_t seed) {
    for (const AcceleratorUnderTest& accelerator : accelerators_under_test()) {
        const Conformance c = compare_with_brute_force(accelerator, meshes, mixed_rays(meshes, origins, count, seed), seed);
        INFO(accelerator.label << ": " << c.mismatches << " answers of " << c.rays << " rays differ from bruteforce\n" << c.report);
        CHECK(c.mismatches == 0);
    }
}

std::vector<std::uint32_t> triangles_of_leaf(const KdTree& tree, const KdTreeNode& leaf) {
    if (leaf.triangle_count() == 1) return {leaf.one_triangle()};
    const auto begin = tree.leaf_triangles.begin() + leaf.triangle_offset();
    return {begin, begin + leaf.triangle_count()};
}

// Calls f(leaf, cell, depth) for every leaf.
void for_each_leaf(const KdTree& tree, const std::function<void(const KdTreeNode&, const Bounds3&, int)>& f) {
    std::function<void(std::uint32_t, const Bounds3&, int)> visit = [&](std::uint32_t index, const Bounds3& cell, int depth) {
        const KdTreeNode& node = tree.nodes[index];
        if (node.is_leaf()) return f(node, cell, depth);
        Bounds3 below = cell, above = cell;
        below.max[node.split_axis()] = node.split_position();
        above.min[node.split_axis()] = node.split_position();
        visit(index + 1, below, depth + 1);
        visit(node.above_child(), above, depth + 1);
    };
    if (!tree.nodes.empty()) visit(0, tree.bounds, 0);
}

// Does some leaf whose closed cell contains p hold the triangle?
bool some_leaf_holds(const KdTree& tree, std::uint32_t index, const glm::dvec3& p, std::uint32_t triangle) {
    const KdTreeNode& node = tree.nodes[index];
    if (node.is_leaf()) {
        for (std::uint32_t t : triangles_of_leaf(tree, node))
            if (t == triangle) return true;
        return false;
    }
    const double split = node.split_position();
    const double x = p[node.split_axis()];
    return (x <= split && some_leaf_holds(tree, index + 1, p, triangle)) ||
           (x >= split && some_leaf_holds(tree, node.above_child(), p, triangle));
}

std::vector<ch06::TriangleVertices> vertices_of(const std::vector<TriangleMesh>& meshes) {
    std::vector<ch06::TriangleVertices> v;
    for (const TriangleMesh& m : meshes)
        for (const auto& t : m.triangles) v.push_back({m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]});
    return v;
}

}  // namespace

TEST_CASE("kdtree: no triangles, one triangle, identical triangles, triangles in one plane", "[unit][kdtree]") {
    SECTION("no meshes, and a mesh without triangles: no nodes, every ray misses") {
        for (const std::vector<TriangleMesh>& meshes : {std::vector<TriangleMesh>{}, std::vector<TriangleMesh>{make_mesh({}, {})}}) {
            KdTreeAccelerator tree;
            tree.build(meshes);
            CHECK(tree.tree().nodes.empty());
            CHECK(tree.statistics().nodes == 0);
            CHECK_FALSE(tree.intersect(Ray{Vec3(0.0f), Vec3(0, 0, 1)}));
            CHECK_FALSE(tree.occluded(Ray{Vec3(0.0f), Vec3(0, 0, 1)}));
        }
    }
    SECTION("one triangle") {
        const std::vector<TriangleMesh> meshes{make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5f}}, {{0, 1, 2}})};
        KdTreeAccelerator tree;
        tree.build(meshes);
        CHECK(tree.statistics().leaves >= 1);
        CHECK(tree.intersect(Ray{Vec3(0.25f, 0.25f, -1.0f), Vec3(0, 0, 1)}));
        check_conformance(meshes, box(Vec3(-1.0f), Vec3(2.0f)), 20000, 30);
    }
    SECTION("200 copies of one triangle, and 50 more in a second mesh: the lowest index wins every tie") {
        std::vector<std::array<std::uint32_t, 3>> copies(200, {0u, 1u, 2u});
        const std::vector<Vec3> p{{0, 0, 0}, {1, 0.2f, 0.1f}, {0.3f, 1, 0.7f}};
        const std::vector<TriangleMesh> meshes{make_mesh(p, copies), make_mesh(p, {copies.begin(), copies.begin() + 50})};
        KdTreeAccelerator tree;
        tree.build(meshes);
        CHECK(tree.statistics().max_depth <= tree.statistics().depth_limit);
        const auto hit = tree.intersect(Ray{Vec3(0.4f, 0.4f, -2.0f), Vec3(0, 0, 1)});
        REQUIRE(hit);
        CHECK(hit->mesh == 0);
        CHECK(hit->triangle == 0);
        check_conformance(meshes, box(Vec3(-1.0f), Vec3(2.0f)), 20000, 31);
    }
    SECTION("300 overlapping triangles in the plane z = 0.25: a flat root cell") {
        TriangleMesh soup = random_soup(300, 0.3f, 32);
        for (Vec3& v : soup.positions) v.z = 0.25f;
        const std::vector<TriangleMesh> meshes{soup};
        KdTreeAccelerator tree;
        tree.build(meshes);
        CHECK(tree.tree().bounds.min.z == tree.tree().bounds.max.z);
        CHECK(tree.statistics().leaves > 1);
        check_conformance(meshes, box(Vec3(-0.5f), Vec3(1.5f)), 30000, 33);
    }
    SECTION("axis-aligned squares stacked in planes of x, y and z") {
        std::vector<TriangleMesh> meshes;
        for (int axis = 0; axis < 3; ++axis)
            for (int i = 0; i < 5; ++i) {
                std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
                for (Vec3& v : p) {
                    v.z = 0.25f * static_cast<float>(i);
                    v = axis == 0 ? Vec3(v.z, v.x, v.y) : axis == 1 ? Vec3(v.y, v.z, v.x) : v;
                }
                meshes.push_back(make_mesh(p, {{0, 1, 2}, {0, 2, 3}}));
            }
        check_conformance(meshes, box(Vec3(-0.5f), Vec3(1.5f)), 50000, 34);
    }
}

TEST_CASE("kdtree: two builds of a scene give identical trees", "[unit][kdtree]") {
    const std::vector<TriangleMesh> meshes{random_soup(2000, 0.1f, 40), icosphere(2, 0.4f, Vec3(0.5f)), planar_grid(8, 0.5f)};
    KdTreeAccelerator first, second;
    first.build(meshes);
    second.build(meshes);
    CHECK(first.tree().nodes.size() > 100);
    CHECK(first.tree().nodes == second.tree().nodes);
    CHECK(first.tree().leaf_triangles == second.tree().leaf_triangles);
}

TEST_CASE("kdtree: the root's radix sort gives the order of operator<", "[unit][kdtree]") {
    // Positions drawn from a few values, so that many events share a position (and type),
    // with both zeros, which compare equal, negatives, huge and tiny ones, and flat boxes
    // (planar events). Events are added in triangle order, as the build adds the root's.
    const std::vector<float> values{-0.0f, 0.0f, -1e30f, -2.5f, -1e-30f, 1e-38f, 0.75f, 1.0f, 3e7f, 1e30f};
    std::mt19937 random(43);
    std::uniform_int_distribution<std::size_t> pick(0, values.size() - 1);
    ch06::NodeEvents events;
    for (std::uint32_t triangle = 0; triangle < 20000; ++triangle) {
        Bounds3 box;
        box.expand(Vec3(values[pick(random)], values[pick(random)], values[pick(random)]));
        box.expand(Vec3(values[pick(random)], values[pick(random)], values[pick(random)]));
        ch06::add_triangle_events(events, triangle, box);
    }
    ch06::NodeEvents by_radix = events, by_comparison = events;
    for (auto& list : by_radix) ch06::sort_events_added_in_triangle_order(list);
    ch06::sort_events(by_comparison);
    for (std::size_t axis = 0; axis < 3; ++axis) {
        REQUIRE(by_radix[axis].size() == by_comparison[axis].size());
        CHECK(std::count_if(by_radix[axis].begin(), by_radix[axis].end(),
                            [](const ch06::SplitEvent& e) { return e.type == ch06::EventType::Planar; }) > 1000);
        bool same = true;
        for (std::size_t i = 0; i < by_radix[axis].size(); ++i) {
            const ch06::SplitEvent &a = by_radix[axis][i], &b = by_comparison[axis][i];
            same = same && a.triangle == b.triangle && a.type == b.type && a.position == b.position;
        }
        CHECK(same);
    }
}

TEST_CASE("kdtree: a build on several threads gives the tree of a build on one", "[unit][kdtree]") {
    // Subtrees built on their own threads are joined in depth-first order with their indices
    // moved: any slip in that (a child index, a leaf list's offset) changes the arrays.
    const std::vector<TriangleMesh> meshes{random_soup(30000, 0.02f, 41), icosphere(3, 0.4f, Vec3(0.5f)), planar_grid(8, 0.5f)};
    ch06::KdTreeSettings one_thread, many_threads;
    one_thread.build_threads = 1;
    many_threads.build_threads = 2;  // the top 3 levels split over threads: up to 8 subtrees at once
    KdTreeAccelerator serial(one_thread), parallel(many_threads);
    serial.build(meshes);
    parallel.build(meshes);
    CHECK(serial.statistics().build_threads == 1);
    CHECK(parallel.statistics().build_threads > 2);  // more than the root's split: nodes of depth 1 too
    CHECK(parallel.statistics().build_threads <= 8);
    REQUIRE(serial.tree().nodes.size() > 1000);
    CHECK(serial.tree().nodes == parallel.tree().nodes);
    CHECK(serial.tree().leaf_triangles == parallel.tree().leaf_triangles);
    CHECK(serial.statistics().leaves == parallel.statistics().leaves);
    CHECK(serial.statistics().triangle_references == parallel.statistics().triangle_references);
    CHECK(serial.statistics().max_depth == parallel.statistics().max_depth);
    CHECK(serial.statistics().mean_leaf_depth == Approx(parallel.statistics().mean_leaf_depth));
}

TEST_CASE("kdtree: the traversal's counts of its work", "[unit][kdtree]") {
    // One triangle: the root is a leaf; a ray that meets the bounds visits it and tests the
    // triangle once, a ray that misses the bounds visits nothing.
    const std::vector<TriangleMesh> one{make_mesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}})};
    KdTreeAccelerator single;
    single.build(one);
    const ch06::TraversalCounts hit = single.count_traversal(Ray{Vec3(0.2f, 0.2f, 1), Vec3(0, 0, -1)});
    CHECK(hit.interior_nodes == 0);
    CHECK(hit.leaves == 1);
    CHECK(hit.triangle_tests == 1);
    const ch06::TraversalCounts miss = single.count_traversal(Ray{Vec3(5, 5, 1), Vec3(0, 0, -1)});
    CHECK(miss.interior_nodes + miss.leaves + miss.triangle_tests == 0);
    // A soup: every ray that hits tested at least its triangle; a walk of more than one leaf
    // passes interior nodes; the answers are intersect's.
    const std::vector<TriangleMesh> soup{random_soup(2000, 0.05f, 42)};
    KdTreeAccelerator tree;
    tree.build(soup);
    PCG32 random(43, 43);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 origin(random.next_float() * 2 - 0.5f, random.next_float() * 2 - 0.5f, -1.0f);
        const Ray ray{origin, glm::normalize(Vec3(random.next_float() - 0.5f, random.next_float() - 0.5f, 1.0f))};
        const ch06::TraversalCounts counts = tree.count_traversal(ray);
        if (tree.intersect(ray)) {
            ++hits;
            CHECK(counts.triangle_tests >= 1);
            CHECK(counts.leaves >= 1);
        }
        if (counts.leaves > 1) CHECK(counts.interior_nodes >= 1);
    }
    CHECK(hits > 100);
}

TEST_CASE("kdtree: rays with NaN, infinite or zero components hit nothing and end", "[unit][kdtree]") {
    const std::vector<TriangleMesh> meshes{icosphere(2), planar_grid(4, 0.0f)};
    KdTreeAccelerator tree;
    tree.build(meshes);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const Ray bad[] = {
        {Vec3(nan, 0, 0), Vec3(0, 0, 1)},      {Vec3(0, 0, 0), Vec3(nan, 0, 1)},
        {Vec3(0, 0, 0), Vec3(nan)},             {Vec3(inf, 0, 0), Vec3(-1, 0, 0)},
        {Vec3(-inf, 0.1f, 0.2f), Vec3(1, 0, 0)}, {Vec3(0, 0, 0), Vec3(inf, 0, 0)},
        {Vec3(0, 0, 0), Vec3(inf, -inf, 1)},    {Vec3(0, 0, 0), Vec3(0, 0, 0)},
        {Vec3(0.1f, 0.2f, 0.3f), Vec3(0, 0, 1), nan}, {Vec3(0.1f, 0.2f, 0.3f), Vec3(0, 0, 1), -1.0f},
        {Vec3(0.1f, 0.2f, 0.3f), Vec3(0, 0, 1), 0.0f},
    };
    for (const Ray& ray : bad) {
        INFO(describe_ray(ray));
        CHECK_FALSE(tree.intersect(ray));
        CHECK_FALSE(tree.occluded(ray));
    }
    // Valid rays with zero components, from origins on the grid's plane and its edges: these hit.
    CHECK(tree.intersect(Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}));
    CHECK(tree.intersect(Ray{Vec3(0.5f, 0.5f, 0), Vec3(1, 0, 0)}));
    CHECK(tree.intersect(Ray{Vec3(0, 0, 0), Vec3(0, 1e-30f, -1)}));
}

TEST_CASE("kdtree: every point of every triangle lies in a leaf that holds it", "[unit][kdtree]") {
    const std::vector<TriangleMesh> meshes{random_soup(1500, 0.2f, 50), planar_grid(8, 0.5f), icosphere(2, 0.3f, Vec3(0.5f))};
    const auto triangles = vertices_of(meshes);
    ch06::KdTreeStatistics statistics;
    const KdTree tree = ch06::build_kdtree(triangles, ch06::KdTreeSettings{}, statistics);
    PCG32 random(51, 51);
    int missing = 0;
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
        const glm::dvec3 a(triangles[i].p0), b(triangles[i].p1), c(triangles[i].p2);
        std::vector<glm::dvec3> points{a, b, c, 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)};
        for (int k = 0; k < 20; ++k) {
            double u = random.next_double(), v = random.next_double();
            if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
            points.push_back(a + u * (b - a) + v * (c - a));
        }
        for (const glm::dvec3& p : points) missing += some_leaf_holds(tree, 0, p, i) ? 0 : 1;
    }
    CHECK(missing == 0);
}

TEST_CASE("kdtree: perfect splits keep a diagonal triangle out of the cells it does not meet", "[unit][kdtree]") {
    // A triangle in the plane x = y fills the box [0, 1]^3 with its bounds; two clusters of small
    // triangles lie far from that plane. Without clipping the diagonal triangle would be in every
    // leaf of its bounding box, the clusters' leaves included.
    std::vector<TriangleMesh> meshes{make_mesh({{0, 0, 0}, {1, 1, 0}, {0, 0, 1}}, {{0, 1, 2}})};
    for (const Vec3& centre : {Vec3(0.9f, 0.1f, 0.5f), Vec3(0.1f, 0.9f, 0.5f)}) {
        TriangleMesh cluster = random_soup(60, 0.02f, 60);
        for (Vec3& v : cluster.positions) v = centre + 0.1f * (v - Vec3(0.5f));
        meshes.push_back(cluster);
    }
    KdTreeAccelerator accelerator;
    accelerator.build(meshes);
    const KdTree& tree = accelerator.tree();
    int leaves_with_diagonal = 0, cluster_leaves_without_it = 0;
    for_each_leaf(tree, [&](const KdTreeNode& leaf, const Bounds3& cell, int) {
        const auto triangles = triangles_of_leaf(tree, leaf);
        const bool has_diagonal = !triangles.empty() && triangles.front() == 0;
        if (has_diagonal) {
            ++leaves_with_diagonal;
            // The cell meets the plane x = y within the triangle's extent.
            CHECK(cell.min.x <= cell.max.y);
            CHECK(cell.min.y <= cell.max.x);
        } else if (!triangles.empty()) {
            ++cluster_leaves_without_it;
        }
    });
    CHECK(leaves_with_diagonal >= 1);
    CHECK(cluster_leaves_without_it >= 2);
}

TEST_CASE("kdtree: the statistics describe the tree", "[unit][kdtree]") {
    const std::vector<TriangleMesh> meshes{random_soup(3000, 0.05f, 70)};
    KdTreeAccelerator accelerator;
    accelerator.build(meshes);
    const ch06::KdTreeStatistics& s = accelerator.statistics();
    const KdTree& tree = accelerator.tree();
    std::size_t leaves = 0, empty = 0, references = 0;
    int deepest = 0;
    double depth_sum = 0.0;
    for_each_leaf(tree, [&](const KdTreeNode& leaf, const Bounds3&, int depth) {
        ++leaves;
        empty += leaf.triangle_count() == 0 ? 1 : 0;
        references += leaf.triangle_count();
        deepest = std::max(deepest, depth);
        depth_sum += depth;
    });
    CHECK(s.triangles == 3000);
    CHECK(s.nodes == tree.nodes.size());
    CHECK(s.nodes == 2 * s.leaves - 1);  // every interior node has two children
    CHECK(s.leaves == leaves);
    CHECK(s.empty_leaves == empty);
    CHECK(s.triangle_references == references);
    CHECK(s.max_depth == deepest);
    CHECK(s.mean_leaf_depth == Approx(depth_sum / static_cast<double>(leaves)));
    CHECK(s.depth_limit == 23);  // round(8 + 1.3 log2 3000)
    CHECK(s.max_depth <= s.depth_limit);
    CHECK(s.memory_bytes >= tree.nodes.size() * 8 + references * 4 + 3000 * sizeof(ch06::TriangleVertices));
    CHECK(s.build_milliseconds > 0.0);
    // A tree, not a list: small leaves, few triangles cut into many.
    CHECK(s.mean_triangles_per_leaf < 8.0);
    CHECK(static_cast<double>(references) / 3000.0 < 4.0);
    CHECK(accelerator.describe().size() >= 5);
}

TEST_CASE("kdtree: settings from a JSON object, with errors that name the place", "[unit][kdtree]") {
    const nlohmann::json json = {{"traversal_cost", 1.0}, {"intersection_cost", 80.0}, {"empty_bonus", 0.5},
                                 {"max_depth", 40}, {"leaf_size", 1}, {"max_unproductive_refinements", 3},
                                 {"build_threads", 2}};
    const ch06::KdTreeSettings s = ch06::read_kdtree_settings(Parameters(json, "scene.json", "/accelerator", "."));
    CHECK(s.traversal_cost == 1.0f);
    CHECK(s.intersection_cost == 80.0f);
    CHECK(s.empty_bonus == 0.5f);
    CHECK(s.max_depth == 40);
    CHECK(s.leaf_size == 1);
    CHECK(s.max_unproductive_refinements == 3);
    CHECK(s.build_threads == 2);
    const nlohmann::json empty = nlohmann::json::object();
    const ch06::KdTreeSettings d = ch06::read_kdtree_settings(Parameters(empty, "scene.json", "/accelerator", "."));
    CHECK(d.traversal_cost == ch06::KdTreeSettings{}.traversal_cost);
    CHECK(d.max_depth == 0);
    for (const auto& [key, value] : std::vector<std::pair<std::string, nlohmann::json>>{
             {"traversal_cost", 0.0}, {"empty_bonus", 1.0}, {"max_depth", 65}, {"leaf_size", -1}, {"max_depth", 2.5},
             {"build_threads", -1}}) {
        const nlohmann::json bad = {{key, value}};
        INFO(key << " = " << value);
        try {
            ch06::read_kdtree_settings(Parameters(bad, "scene.json", "/accelerator", "."));
            FAIL("no error");
        } catch (const InputError& e) {
            CHECK(e.where() == "scene.json: /accelerator/" + key);
        }
    }
    // The automatic depth, and the stack's cap.
    ch06::KdTreeSettings automatic;
    CHECK(ch06::effective_max_depth(automatic, 1) == 8);
    CHECK(ch06::effective_max_depth(automatic, 262267) == 31);
    CHECK(ch06::effective_max_depth(automatic, std::size_t(1) << 60) == ch06::TraversalStackSize);
}

TEST_CASE("kdtree: a renderer before chapter 06 names the chapter that introduces it", "[unit][kdtree]") {
    Registry registry("ch05", 5);
    register_chapter05(registry);
    try {
        registry.accelerators.make("kdtree", "--accel", Parameters::none());
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("introduced in chapter 06"));
    }
    CHECK(full_registry().has(CapabilityKind::Accelerator, "kdtree"));
}
