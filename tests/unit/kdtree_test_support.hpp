// Meshes, rays and the brute-force comparison of the KD-tree tests.
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/mesh.hpp"
#include "freezeray/random.hpp"
#include "freezeray/ray.hpp"
#include "freezeray/registry.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace freezeray::testing {



// An accelerator as a test builds it: its registered name and the settings it is made with
// ("simd_width": 4), under a label for messages ("kdtree-simd (width 4)").
struct AcceleratorUnderTest {
    std::string label;
    std::string name;
    nlohmann::json settings = nlohmann::json::object();
    std::unique_ptr<Accelerator> make() const;
};

// The accelerators that must agree with brute force on every ray: every accelerator the
// complete renderer has but brute force itself, and chapter 07's kdtree-simd at every packet
// width this processor runs.
const std::vector<AcceleratorUnderTest>& accelerators_under_test();

TriangleMesh make_mesh(std::vector<Vec3> positions, std::vector<std::array<std::uint32_t, 3>> triangles);

// A closed unit sphere: an icosahedron subdivided `levels` times (20 * 4^levels triangles).
TriangleMesh icosphere(int levels, float radius = 1.0f, const Vec3& centre = Vec3(0.0f));

// n triangles with random vertices near random centres in [0, 1]^3, edges up to `size`.
TriangleMesh random_soup(int n, float size, std::uint64_t seed);

// A grid of n x n squares (two triangles each) covering [-1, 1]^2 in the plane z = height.
TriangleMesh planar_grid(int n, float height);

// Rays of every kind over the meshes: random origins and directions, rays aimed at vertices and
// at points of edges, axis-parallel rays through vertices (exactly) and through random points,
// some with a finite tmax. Origins within `origins` (which may be larger than the scene).
std::vector<Ray> mixed_rays(const std::vector<TriangleMesh>& meshes, const Bounds3& origins, int count,
                            std::uint64_t seed);

// The ray written exactly (hexadecimal floats), for failure messages.
std::string describe_ray(const Ray& ray);

struct Conformance {
    std::size_t rays = 0;
    std::size_t mismatches = 0;  // intersect or occluded answers that differ
    std::string report;          // the first mismatches with their rays
};

// Builds `accelerator` and bruteforce over the meshes and compares, for every ray, intersect
// (no hit, or the same mesh, triangle and t bits), and occluded and occluded_by (half the
// triangles counted, chosen by coin) with a random tmax.
Conformance compare_with_brute_force(const AcceleratorUnderTest& accelerator, const std::vector<TriangleMesh>& meshes,
                                     const std::vector<Ray>& rays, std::uint64_t seed);

}  // namespace freezeray::testing
