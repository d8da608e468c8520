// The KD-tree finds exactly what brute force finds: for 1.1 million rays over closed,
// open, flat, dense, tiny and far geometry, the same triangle of the same mesh at the same t
// (bit for bit) from intersect, and the same answer from occluded with a random tmax. Rays
// aimed at vertices and shared edges, along the axes, inside split planes and from origins on
// them are the hard part: there the rounding of the cells' ranges and of the triangles' t
// decides which cells a ray visits.
#include "kdtree_test_support.hpp"
#include "test_bounds.hpp"

#include "freezeray/ch06/kdtree_accelerator.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/ch01/warps.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;
using namespace freezeray::testing;

namespace {

void check_conformance(const std::string& what, const std::vector<TriangleMesh>& meshes, const std::vector<Ray>& rays,
                       std::uint64_t seed) {
    for (const AcceleratorUnderTest& accelerator : accelerators_under_test()) {
        const Conformance c = compare_with_brute_force(accelerator, meshes, rays, seed);
        INFO(what << ": " << accelerator.label << ": " << c.mismatches << " answers of " << c.rays << " rays differ from bruteforce\n"
                  << c.report);
        CHECK(c.rays == rays.size());
        CHECK(c.mismatches == 0);
    }
}

Bounds3 bounds_of(const std::vector<TriangleMesh>& meshes) {
    Bounds3 b;
    for (const TriangleMesh& m : meshes) b.expand(m.bounds());
    return b;
}

std::vector<TriangleMesh> scene_meshes(const std::string& relative) {
    return load_scene(scene_path(relative), full_registry()).meshes;
}

// Rays from `origin` towards uniform points of `target`.
void add_rays_towards(std::vector<Ray>& rays, const Vec3& origin, const Bounds3& target, int count, std::uint64_t seed) {
    PCG32 random(seed, 17);
    for (int i = 0; i < count; ++i) {
        const Vec3 p = target.min + target.diagonal() * Vec3(random.next_float(), random.next_float(), random.next_float());
        rays.push_back(Ray{origin, glm::normalize(p - origin)});
    }
}

void append(std::vector<Ray>& rays, const std::vector<Ray>& more) { rays.insert(rays.end(), more.begin(), more.end()); }

}  // namespace

TEST_CASE("kdtree: a closed tessellated sphere, from inside and outside (100000 rays)", "[unit][kdtree]") {
    const std::vector<TriangleMesh> meshes{icosphere(2)};  // 320 triangles
    std::vector<Ray> rays = mixed_rays(meshes, box(Vec3(-0.55f), Vec3(0.55f)), 50000, 1);
    append(rays, mixed_rays(meshes, box(Vec3(-3.0f), Vec3(3.0f)), 50000, 2));
    check_conformance("sphere", meshes, rays, 3);
    // From inside, every ray leaves through the sphere: no ray escapes through a crack.
    const auto tree = full_registry().accelerators.make("kdtree", "test", Parameters::none());
    tree->build(meshes);
    int inside = 0, escaped = 0;
    for (const Ray& ray : rays) {
        if (ray.tmax != INFINITY || glm::length(ray.origin) > 0.95f) continue;
        ++inside;
        escaped += tree->intersect(ray) ? 0 : 1;
    }
    CHECK(inside > 20000);
    CHECK(escaped == 0);
}

TEST_CASE("kdtree: the fan of scenes/hard/fan, through its shared centre vertex and edges (200000 rays)", "[unit][kdtree]") {
    const std::vector<TriangleMesh> meshes = scene_meshes("hard/fan/scene.json");
    std::vector<Ray> rays = mixed_rays(meshes, box(Vec3(-1.5f, -1.5f, -2.0f), Vec3(1.5f, 1.5f, 2.0f)), 160000, 4);
    PCG32 random(5, 5);
    for (int i = 0; i < 20000; ++i) {
        // Exactly through the centre and through points of the four edges along the axes.
        const float r = random.next_float();
        const float z = random.next_float() < 0.5f ? -2.0f : 2.0f;
        const Vec3 d(0.0f, 0.0f, z < 0.0f ? 1.0f : -1.0f);
        const Vec3 points[] = {Vec3(0.0f), Vec3(r, 0, 0), Vec3(-r, 0, 0), Vec3(0, r, 0), Vec3(0, -r, 0)};
        const Vec3& p = points[i % 5];
        rays.push_back(Ray{Vec3(p.x, p.y, z), d});
        // Obliquely at the same points (through them up to the rounding of the origin).
        const Vec3 oblique = glm::normalize(d + 0.5f * (ch01::sample_uniform_sphere(Vec2(random.next_float(), random.next_float())) * Vec3(1, 1, 0)));
        rays.push_back(Ray{p - 2.0f * oblique, oblique});
    }
    check_conformance("fan", meshes, rays, 6);
    // Exactly one triangle answers every ray through the centre (a crack would let it through).
    const auto tree = full_registry().accelerators.make("kdtree", "test", Parameters::none());
    tree->build(meshes);
    CHECK(tree->intersect(Ray{Vec3(0, 0, -2), Vec3(0, 0, 1)}));
    CHECK(tree->intersect(Ray{Vec3(0, 0, 2), Vec3(0, 0, -1)}));
}

TEST_CASE("kdtree: the Cornell box, camera rays and rays of every kind (300000 rays)", "[unit][kdtree]") {
    const Scene scene = load_scene(scene_path("cornell-box/scene.json"), full_registry());
    const Bounds3 bounds = bounds_of(scene.meshes);
    std::vector<Ray> rays;
    add_rays_towards(rays, scene.camera_description.position, bounds, 100000, 7);
    const Vec3 margin = 0.1f * bounds.diagonal();
    append(rays, mixed_rays(scene.meshes, box(bounds.min - margin, bounds.max + margin), 200000, 8));
    check_conformance("cornell-box", scene.meshes, rays, 9);
}

TEST_CASE("kdtree: a dense soup of crossing random triangles (100000 rays)", "[unit][kdtree]") {
    const std::vector<TriangleMesh> meshes{random_soup(200, 0.3f, 10), random_soup(60, 0.05f, 11)};
    const std::vector<Ray> rays = mixed_rays(meshes, box(Vec3(-0.5f), Vec3(1.5f)), 100000, 12);
    check_conformance("soup", meshes, rays, 13);
}

TEST_CASE("occluded_by: the default walk of closest hits answers as bruteforce's any-hit over the counted triangles", "[unit][kdtree]") {
    // The accelerators without a walk of their own (the benchmark's Embree) use Accelerator's
    // default; bruteforce overrides it with an any-hit loop, as the trees do. Random rays through
    // a dense soup, half its triangles counted; then none counted (nothing blocks) and all
    // counted (occluded's answer).
    const std::vector<TriangleMesh> meshes{random_soup(200, 0.3f, 20), random_soup(60, 0.05f, 21)};
    const auto brute_force = full_registry().accelerators.make("bruteforce", "test", Parameters::none());
    brute_force->build(meshes);
    PCG32 random(22, 23);
    TriangleFlags half, none, all;
    for (const TriangleMesh& mesh : meshes) {
        half.emplace_back(mesh.triangles.size());
        for (std::uint8_t& flag : half.back()) flag = static_cast<std::uint8_t>(random.next_below(2));
        none.emplace_back(mesh.triangles.size(), 0);
        all.emplace_back(mesh.triangles.size(), 1);
    }
    int blocked = 0, differ = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 origin(random.next_float(), random.next_float(), random.next_float());  // inside the soup
        Ray ray{origin, ch01::sample_uniform_sphere(Vec2(random.next_float(), random.next_float()))};
        ray.tmax = 2.0f * random.next_float();
        const bool any_hit = brute_force->occluded_by(ray, half);
        blocked += any_hit;
        differ += any_hit != brute_force->Accelerator::occluded_by(ray, half);
        CHECK_FALSE(brute_force->occluded_by(ray, none));
        CHECK(brute_force->occluded_by(ray, all) == brute_force->occluded(ray));
    }
    CHECK(differ == 0);
    INFO(blocked << " of 20000 rays blocked");
    CHECK(blocked > 2000);  // the rays met counted triangles often enough to test the walk
    CHECK(blocked < 18000);
}

TEST_CASE("kdtree: a planar grid lying in a split plane, with rays in it and from it (150000 rays)", "[unit][kdtree]") {
    // The grid at z = 0 crosses a sphere; walls stand on it with their lower edges in z = 0.
    std::vector<TriangleMesh> meshes{planar_grid(8, 0.0f), icosphere(1, 0.5f)};
    meshes.push_back(make_mesh({{-0.75f, -0.75f, 0}, {0.75f, -0.75f, 0}, {0.75f, -0.75f, 0.5f}, {-0.75f, -0.75f, 0.5f},
                                {-0.75f, 0.75f, 0}, {-0.75f, 0.75f, -0.5f}, {0.25f, 0.75f, -0.5f}},
                               {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}}));
    {
        // The premise: some node of the tree splits at z = 0 exactly.
        ch06::KdTreeAccelerator tree;
        tree.build(meshes);
        bool splits_at_zero = false;
        for (const ch06::KdTreeNode& node : tree.tree().nodes)
            splits_at_zero |= !node.is_leaf() && node.split_axis() == 2 && node.split_position() == 0.0f;
        REQUIRE(splits_at_zero);
    }
    std::vector<Ray> rays = mixed_rays(meshes, box(Vec3(-1.25f), Vec3(1.25f)), 100000, 14);
    PCG32 random(15, 15);
    for (int i = 0; i < 25000; ++i) {
        const Vec3 o(2.5f * random.next_float() - 1.25f, 2.5f * random.next_float() - 1.25f, 0.0f);
        Vec3 d = ch01::sample_uniform_sphere(Vec2(random.next_float(), random.next_float()));
        rays.push_back(Ray{o, d});  // from an origin on the plane
        d.z = 0.0f;
        rays.push_back(Ray{o, glm::normalize(d)});  // in the plane
    }
    check_conformance("grid", meshes, rays, 16);
}

TEST_CASE("kdtree: far and tiny geometry of scenes/hard (250000 rays)", "[unit][kdtree]") {
    {
        // A 2e-3 cube in an enclosure 2e5 across.
        const Scene scene = load_scene(scene_path("hard/far-and-tiny/scene.json"), full_registry());
        const Bounds3 cube = scene.meshes[1].bounds();
        std::vector<Ray> rays;
        add_rays_towards(rays, scene.camera_description.position, cube, 50000, 17);
        append(rays, mixed_rays(scene.meshes, box(Vec3(-0.01f), Vec3(0.01f)), 50000, 18));
        append(rays, mixed_rays(scene.meshes, bounds_of(scene.meshes), 50000, 19));
        check_conformance("far-and-tiny", scene.meshes, rays, 20);
    }
    {
        // Triangles whose edges are one ulp of their coordinates.
        const Scene scene = load_scene(scene_path("hard/tiny-triangle/scene.json"), full_registry());
        std::vector<Ray> rays;
        const TriangleMesh& tiny = scene.meshes.back();
        for (const auto& t : tiny.triangles) {
            Bounds3 triangle;
            for (std::uint32_t v : t) triangle.expand(tiny.positions[v]);
            add_rays_towards(rays, scene.camera_description.position, triangle, 10000, 21);
        }
        const Vec3 camera = scene.camera_description.position;
        append(rays, mixed_rays(scene.meshes, box(camera - Vec3(1e-11f), camera + Vec3(1e-11f)), 40000, 22));
        append(rays, mixed_rays(scene.meshes, bounds_of(scene.meshes), 40000, 23));
        check_conformance("tiny-triangle", scene.meshes, rays, 24);
    }
}
