// Measuring and comparing answers (chapters/06-kd-tree/benchmark/throughput.cpp,
// ray_answers.cpp): every ray of a batch is traced whatever the thread count, and disagreements
// are counted the documented way. No timing is asserted: timings belong to benchmarks.
#include "ray_answers.hpp"
#include "throughput.hpp"

#include "freezeray/accelerator.hpp"
#include "freezeray/random.hpp"
#include "freezeray/ch01/warps.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;
using namespace freezeray::benchmark;

namespace {

// A 10 x 10 grid of unit squares in the plane z = 0, two triangles each.
std::vector<TriangleMesh> grid() {
    TriangleMesh mesh;
    for (int y = 0; y <= 10; ++y)
        for (int x = 0; x <= 10; ++x) mesh.positions.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.0f);
    for (std::uint32_t y = 0; y < 10; ++y)
        for (std::uint32_t x = 0; x < 10; ++x) {
            const std::uint32_t v = y * 11 + x;
            mesh.triangles.push_back({v, v + 1, v + 12});
            mesh.triangles.push_back({v, v + 12, v + 11});
        }
    mesh.face_materials.assign(mesh.triangles.size(), 0u);
    return {mesh};
}

// Rays from above towards random points of a slightly larger square, so that some miss.
std::vector<Ray> random_rays(std::size_t count, float tmax) {
    PCG32 random(3, 5);
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 origin(random.next_float() * 12.0f - 1.0f, random.next_float() * 12.0f - 1.0f, 5.0f);
        const Vec3 direction = glm::normalize(Vec3(random.next_float() - 0.5f, random.next_float() - 0.5f, -1.0f));
        rays.push_back(Ray{origin, direction, tmax});
    }
    return rays;
}

}  // namespace

TEST_CASE("throughput: every ray is answered, the same on 1, 2, 3 and 7 threads", "[unit][ray-benchmark]") {
    const std::vector<TriangleMesh> meshes = grid();
    BruteForceAccelerator accelerator;
    accelerator.build(meshes);
    // Four whole chunks and part of a fifth, so that threads share the batch.
    const std::vector<Ray> rays = random_rays(4 * ChunkRays + 5, std::numeric_limits<float>::infinity());
    std::vector<ClosestHit> expected;
    for (const Ray& ray : rays) {
        const std::optional<Hit> hit = accelerator.intersect(ray);
        expected.push_back(hit ? ClosestHit{static_cast<std::int32_t>(hit->triangle), hit->t} : ClosestHit{});
    }
    std::size_t misses = 0;
    for (const ClosestHit& hit : expected) misses += hit.is_miss() ? 1 : 0;
    REQUIRE(misses > 0);
    REQUIRE(misses < rays.size());

    for (int threads : {1, 2, 3, 7}) {
        INFO(threads << " threads");
        const ThroughputMeasurement measurement = measure_throughput(accelerator, rays, RayKind::Diffuse, threads, 3);
        CHECK(measurement.run_seconds.size() == 3);
        CHECK(measurement.answers.closest == expected);
        CHECK(measurement.answers.occluded.empty());
        CHECK(measurement.mrays_per_second(rays.size()) > 0.0);
    }
}

TEST_CASE("throughput: shadow rays are asked whether anything lies before tmax", "[unit][ray-benchmark]") {
    const std::vector<TriangleMesh> meshes = grid();
    BruteForceAccelerator accelerator;
    accelerator.build(meshes);
    const std::vector<Ray> short_rays = random_rays(200, 4.0f);   // the grid is at least 5 away
    const std::vector<Ray> long_rays = random_rays(200, 100.0f);  // reach it
    const ThroughputMeasurement short_answers = measure_throughput(accelerator, short_rays, RayKind::Shadow, 2, 1);
    const ThroughputMeasurement long_answers = measure_throughput(accelerator, long_rays, RayKind::Shadow, 2, 1);
    REQUIRE(short_answers.answers.occluded.size() == 200);
    for (std::size_t i = 0; i < 200; ++i) {
        INFO("ray " << i);
        CHECK(short_answers.answers.occluded[i] == 0);
        CHECK(long_answers.answers.occluded[i] == (accelerator.intersect(long_rays[i]) ? 1 : 0));
    }
}

TEST_CASE("median: the middle value, or the mean of the middle two", "[unit][ray-benchmark]") {
    CHECK(median({}) == 0.0);
    CHECK(median({3.0}) == 3.0);
    CHECK(median({5.0, 1.0, 3.0}) == 3.0);
    CHECK(median({4.0, 1.0, 2.0, 10.0}) == 3.0);
}

TEST_CASE("disagreements: hit against miss and different triangles differ; equal distances are ties",
          "[unit][ray-benchmark]") {
    RayAnswers reference, answers;
    reference.closest = {ClosestHit{1, 2.0f}, ClosestHit{}, ClosestHit{3, 10.0f}, ClosestHit{4, 10.0f},
                         ClosestHit{5, 100.0f}, ClosestHit{}, ClosestHit{7, 1.0f}};
    answers.closest = {ClosestHit{1, 2.0f + 1e-5f},  // same triangle, t rounded differently: agrees
                       ClosestHit{2, 5.0f},          // hit where the reference misses: differs
                       ClosestHit{},                 // miss where the reference hits: differs
                       ClosestHit{9, 10.0f},         // another triangle at the same t: a tie
                       ClosestHit{6, 100.00005f},    // within a relative 1e-6 (one float step): a tie
                       ClosestHit{},                 // both miss: agrees
                       ClosestHit{8, 1.01f}};        // another triangle further away: differs
    reference.occluded = {1, 0, 1};
    answers.occluded = {1, 1, 0};  // two shadow answers differ
    const Disagreements d = compare_answers(answers, reference);
    CHECK(d.differ == 3 + 2);
    CHECK(d.ties == 2);
}
