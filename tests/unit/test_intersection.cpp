// Watertight ray-triangle intersection and the brute-force accelerator.
#include "freezeray/accelerator.hpp"
#include "freezeray/random.hpp"
#include "freezeray/triangle_intersection.hpp"
#include "freezeray/ch01/warps.hpp"

#include <catch2/catch.hpp>

#include <map>

using namespace freezeray;
using namespace freezeray::ch01;

namespace {

// Counts how many triangles of the mesh report a hit for the ray, testing each on its own.
int count_hits(const Ray& ray, const TriangleMesh& mesh) {
    const RayShear shear(ray.direction);
    int hits = 0;
    for (const auto& t : mesh.triangles)
        if (intersect_triangle(ray, shear, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]])) ++hits;
    return hits;
}

// A fan of n triangles around a centre vertex in the plane z = 0, consistently wound.
TriangleMesh fan(int n) {
    TriangleMesh mesh;
    mesh.positions.push_back(Vec3(0.0f));
    for (int i = 0; i < n; ++i) {
        const float a = 2.0f * Pi * static_cast<float>(i) / static_cast<float>(n);
        mesh.positions.push_back(Vec3(std::cos(a), std::sin(a), 0.0f));
    }
    for (int i = 0; i < n; ++i)
        mesh.triangles.push_back({0u, static_cast<std::uint32_t>(1 + i), static_cast<std::uint32_t>(1 + (i + 1) % n)});
    mesh.face_materials.assign(mesh.triangles.size(), 0u);
    return mesh;
}

// A closed unit sphere: an icosahedron subdivided `levels` times, projected onto the sphere.
TriangleMesh icosphere(int levels) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    TriangleMesh mesh;
    mesh.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& p : mesh.positions) p = glm::normalize(p);
    mesh.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            mesh.positions.push_back(glm::normalize(mesh.positions[a] + mesh.positions[b]));
            return midpoints[key] = static_cast<std::uint32_t>(mesh.positions.size() - 1);
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto& [a, b, c] : mesh.triangles) {
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({b, bc, ab});
            finer.push_back({c, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = finer;
    }
    mesh.face_materials.assign(mesh.triangles.size(), 0u);
    return mesh;
}

}  // namespace

TEST_CASE("a ray through the middle of a triangle hits it with the right distance and barycentrics", "[unit][intersection]") {
    const Ray ray{Vec3(0.25f, 0.25f, 1.0f), Vec3(0, 0, -1)};
    const auto hit = intersect_triangle(ray, RayShear(ray.direction), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
    REQUIRE(hit);
    CHECK(hit->t == Approx(1.0f));
    CHECK(hit->b1 == Approx(0.25f));
    CHECK(hit->b2 == Approx(0.25f));
    CHECK(hit->b0 == Approx(0.5f));
    // Both windings are hit (the test is two-sided) and the interval (0, tmax) is respected.
    CHECK(intersect_triangle(ray, RayShear(ray.direction), Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0)));
    Ray short_ray = ray;
    short_ray.tmax = 0.999f;
    CHECK_FALSE(intersect_triangle(short_ray, RayShear(ray.direction), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));
    const Ray away{Vec3(0.25f, 0.25f, 1.0f), Vec3(0, 0, 1)};
    CHECK_FALSE(intersect_triangle(away, RayShear(away.direction), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)));
}

TEST_CASE("rays exactly on shared edges and vertices hit exactly one triangle", "[unit][intersection]") {
    const TriangleMesh mesh = fan(8);
    // Through the shared centre vertex, from both sides.
    CHECK(count_hits(Ray{Vec3(0, 0, 1), Vec3(0, 0, -1)}, mesh) == 1);
    CHECK(count_hits(Ray{Vec3(0, 0, -1), Vec3(0, 0, 1)}, mesh) == 1);
    // Through points on the shared edges (along the axes, where the coordinates are exact).
    for (float r : {0.125f, 0.25f, 0.5f}) {
        CHECK(count_hits(Ray{Vec3(r, 0, 1), Vec3(0, 0, -1)}, mesh) == 1);
        CHECK(count_hits(Ray{Vec3(0, r, 1), Vec3(0, 0, -1)}, mesh) == 1);
        CHECK(count_hits(Ray{Vec3(-r, 0, -1), Vec3(0, 0, 1)}, mesh) == 1);
        CHECK(count_hits(Ray{Vec3(0, -r, 1), Vec3(0, 0, -1)}, mesh) == 1);
    }
    // Two triangles of a square sharing their diagonal.
    TriangleMesh square;
    square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    square.triangles = {{0, 1, 2}, {0, 2, 3}};
    for (float s : {0.125f, 0.25f, 0.5f, 0.75f}) CHECK(count_hits(Ray{Vec3(s, s, 1), Vec3(0, 0, -1)}, square) == 1);
    // (On the outer boundary of an open mesh the tie-breaking rule may give a point to no
    // triangle, as a rasteriser's top-left rule does: only shared edges are owned exactly once.)
}

TEST_CASE("no ray from inside leaks through a closed tessellated sphere (a million rays)", "[unit][intersection]") {
    std::vector<TriangleMesh> meshes{icosphere(2)};  // 320 triangles
    BruteForceAccelerator accelerator;
    accelerator.build(meshes);
    const TriangleMesh& sphere = meshes[0];
    PCG32 random(2013, 1);
    int leaks = 0;
    constexpr int RayCount = 1'000'000;
    for (int i = 0; i < RayCount; ++i) {
        const Vec3 origin = 0.5f * sample_uniform_sphere(Vec2(random.next_float(), random.next_float())) * random.next_float();
        Vec3 target;
        switch (i % 3) {
            case 0:  // aimed exactly at a vertex, where several triangles meet
                target = sphere.positions[random.next_below(static_cast<std::uint32_t>(sphere.positions.size()))];
                break;
            case 1: {  // aimed at a point of an edge
                const auto& t = sphere.triangles[random.next_below(static_cast<std::uint32_t>(sphere.triangles.size()))];
                const float s = random.next_float();
                target = (1.0f - s) * sphere.positions[t[0]] + s * sphere.positions[t[1]];
                break;
            }
            default:  // anywhere
                target = sample_uniform_sphere(Vec2(random.next_float(), random.next_float()));
        }
        const Ray ray{origin, glm::normalize(target - origin)};
        if (!accelerator.intersect(ray)) ++leaks;
    }
    CHECK(leaks == 0);
}

TEST_CASE("hits carry a position error bound that the spawned ray clears", "[unit][intersection]") {
    for (float scale : {1e-4f, 1.0f, 1e4f}) {
        std::vector<TriangleMesh> meshes(1);
        meshes[0].positions = {Vec3(-1, -1, 3) * scale, Vec3(1, -1, 3) * scale, Vec3(0, 1, 3) * scale};
        meshes[0].triangles = {{0, 1, 2}};
        meshes[0].face_materials = {0};
        BruteForceAccelerator accelerator;
        accelerator.build(meshes);
        const Ray ray{Vec3(0.1f, 0.05f, 0.0f) * scale, glm::normalize(Vec3(0.1f, 0.05f, 3.0f))};
        const auto hit = accelerator.intersect(ray);
        REQUIRE(hit);
        CHECK(glm::dot(hit->geometric_normal, Vec3(0, 0, 1)) == Approx(1.0f));
        // Leaving the surface, on either side, never hits the same triangle again.
        CHECK_FALSE(accelerator.intersect(hit->spawn_ray(glm::normalize(Vec3(0.3f, 0.2f, -1.0f)))));
        CHECK_FALSE(accelerator.intersect(hit->spawn_ray(glm::normalize(Vec3(0.3f, 0.2f, 1.0f)))));
        CHECK_FALSE(accelerator.occluded(hit->spawn_ray_to(Vec3(0.0f))));
    }
}
