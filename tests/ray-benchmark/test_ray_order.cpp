// The coherent order of --order coherent: Morton codes, and a sort that only reorders.
#include "ray_order.hpp"

#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace freezeray;
using namespace freezeray::benchmark;

TEST_CASE("morton code: bits of x, y and z interleaved, corners at the ends", "[unit][ray-benchmark]") {
    Bounds3 box;
    box.expand(Vec3(0.0f));
    box.expand(Vec3(1024.0f));
    CHECK(morton_code(Vec3(0.0f), box) == 0u);
    CHECK(morton_code(Vec3(1024.0f), box) == (1u << 30) - 1);  // clamped to the last cell
    CHECK(morton_code(Vec3(1.0f, 0.0f, 0.0f), box) == 1u);     // x is the lowest bit
    CHECK(morton_code(Vec3(0.0f, 1.0f, 0.0f), box) == 2u);
    CHECK(morton_code(Vec3(0.0f, 0.0f, 1.0f), box) == 4u);
    CHECK(morton_code(Vec3(2.0f, 0.0f, 0.0f), box) == 8u);
    CHECK(morton_code(Vec3(512.0f, 512.0f, 512.0f), box) == 7u << 27);
    CHECK(morton_code(Vec3(-5.0f, 2000.0f, 0.0f), box) == morton_code(Vec3(0.0f, 1023.0f, 0.0f), box));
    Bounds3 flat;
    flat.expand(Vec3(0.0f));
    flat.expand(Vec3(8.0f, 0.0f, 8.0f));
    CHECK(morton_code(Vec3(8.0f, 0.0f, 8.0f), flat) == morton_code(Vec3(8.0f, 5.0f, 8.0f), flat));
}

TEST_CASE("coherent order: the same rays, grouped by octant, origins in Morton order", "[unit][ray-benchmark]") {
    Bounds3 box;
    box.expand(Vec3(-1.0f));
    box.expand(Vec3(1.0f));
    PCG32 random(3, 7);
    RayBatches batches;
    for (std::vector<Ray>& batch : batches.rays)
        for (int i = 0; i < 5000; ++i) {
            const Vec3 origin(2.0f * random.next_float() - 1.0f, 2.0f * random.next_float() - 1.0f, 2.0f * random.next_float() - 1.0f);
            const Vec3 direction = glm::normalize(Vec3(random.next_float() - 0.5f, random.next_float() - 0.5f, random.next_float() - 0.5f));
            batch.push_back(Ray{origin, direction, 1.0f + static_cast<float>(i)});
        }
    const RayBatches original = batches;
    sort_for_coherence(batches, box);
    auto octant = [](const Ray& r) {
        return (r.direction.x < 0.0f ? 4 : 0) | (r.direction.y < 0.0f ? 2 : 0) | (r.direction.z < 0.0f ? 1 : 0);
    };
    for (std::size_t kind = 0; kind < 3; ++kind) {
        const std::vector<Ray>& sorted = batches.rays[kind];
        REQUIRE(sorted.size() == original.rays[kind].size());
        // A permutation: each ray's tmax is its original index + 1, so the tmaxes are all there once.
        std::vector<float> tmax;
        for (const Ray& r : sorted) tmax.push_back(r.tmax);
        std::sort(tmax.begin(), tmax.end());
        bool permutation = true;
        for (std::size_t i = 0; i < tmax.size(); ++i) permutation = permutation && tmax[i] == 1.0f + static_cast<float>(i);
        CHECK(permutation);
        bool ordered = true;
        for (std::size_t i = 1; i < sorted.size(); ++i) {
            const int a = octant(sorted[i - 1]), b = octant(sorted[i]);
            ordered = ordered && (a < b || (a == b && morton_code(sorted[i - 1].origin, box) <= morton_code(sorted[i].origin, box)));
        }
        CHECK(ordered);
    }
}
