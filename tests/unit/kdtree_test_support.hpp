// Meshes, rays and the brute-force comparison of the KD-tree tests.
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/mesh.hpp"
#include "freezeray/random.hpp"
#include "freezeray/ray.hpp"
#include "freezeray/registry.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace freezeray::testing {



// The accelerators that must agree with brute force on every ray. A later chapter's
// accelerator (kdtree-simd) joins this list.
const std::vector<std::string>& accelerators_under_test();

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
// (no hit, or the same mesh, triangle and t bits) and occluded with a random tmax.
Conformance compare_with_brute_force(const std::string& accelerator, const std::vector<TriangleMesh>& meshes,
                                     const std::vector<Ray>& rays, std::uint64_t seed);

}  // namespace freezeray::testing
