// Grading tests of chapter 07's exercises. Each calls its exercise's own code first (so that in a
// student copy it fails through its own stub) and checks it against exact answers: the packet
// layout float by float, and the kernels' hits against the scalar watertight test bit by bit.
// Deterministic: no statistical test in this file.
#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/ch07/packet_kernels.hpp"
#include "freezeray/ch07/triangle_packets.hpp"
#include "freezeray/random.hpp"
#include "freezeray/triangle_intersection.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <string>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch07;

namespace {

// Triangle i has vertex v's coordinate on axis a equal to 100 i + 10 v + a: every float of a
// packet says where it came from.
std::vector<ch06::TriangleVertices> labelled_triangles(int n) {
    std::vector<ch06::TriangleVertices> triangles;
    for (int i = 0; i < n; ++i) {
        auto p = [&](int v) { return Vec3(100.0f * i + 10.0f * v, 100.0f * i + 10.0f * v + 1, 100.0f * i + 10.0f * v + 2); };
        triangles.push_back({p(0), p(1), p(2)});
    }
    return triangles;
}

}  // namespace

TEST_CASE("ch07/structure-of-arrays", "[exercise]") {
    const std::vector<ch06::TriangleVertices> triangles = labelled_triangles(7);
    for (const int width : {1, 4, 8, 16}) {
        for (int count = 1; count <= width && count <= 5; ++count) {
            // The leaf's triangles, in its own order: 6, 2, 4, 0, 5.
            const std::uint32_t leaf[] = {6, 2, 4, 0, 5};
            std::vector<float> coordinates(packet_floats(width), -1.0f);
            std::vector<std::uint32_t> lanes(width, 99u);
            pack_triangles(triangles, leaf, count, width, coordinates.data(), lanes.data());
            INFO("width " << width << ", " << count << " triangles");
            for (int lane = 0; lane < width; ++lane) {
                // A padded lane repeats the last triangle.
                const std::uint32_t expected = leaf[lane < count ? lane : count - 1];
                INFO("lane " << lane);
                REQUIRE(lanes[lane] == expected);
                for (int vertex = 0; vertex < 3; ++vertex)
                    for (int axis = 0; axis < 3; ++axis) {
                        INFO("vertex " << vertex << ", axis " << axis);
                        CHECK(coordinates[(3 * vertex + axis) * width + lane] == 100.0f * expected + 10.0f * vertex + axis);
                    }
            }
        }
    }
}

TEST_CASE("ch07/inside-mask", "[exercise]") {
    // Random triangles of both windings and random rays, plus rays through vertices, which put
    // edge functions at zero. Every kernel this processor runs, narrowest (scalar) first, answers
    // each lane as intersect_triangle does: hit or not, the same t bits.
    PCG32 random(7, 3);
    auto point = [&] { return Vec3(random.next_float(), random.next_float(), random.next_float()) * 2.0f - 1.0f; };
    std::vector<ch06::TriangleVertices> triangles;
    for (int i = 0; i < 64; ++i) {
        ch06::TriangleVertices t{point(), point(), point()};
        if (i % 2) std::swap(t.p1, t.p2);  // the other winding
        triangles.push_back(t);
    }
    std::vector<Ray> rays;
    for (int i = 0; i < 400; ++i) {
        const Vec3 origin = point() * 3.0f;
        const Vec3 target = i % 4 == 0 ? triangles[i % triangles.size()].p0 : point() * 0.5f;
        rays.push_back(Ray{origin, glm::normalize(target - origin)});
    }
    for (const PacketKernel& kernel : built_kernels()) {
        if (!cpu_runs(kernel)) continue;
        const int width = kernel.width;
        std::vector<float, CacheLineAllocator<float>> coordinates(packet_floats(width));
        std::vector<std::uint32_t> lanes(width);
        PacketHits hits;
        int hits_seen = 0, mismatches = 0, both_windings = 0;
        std::string first;
        for (const Ray& ray : rays) {
            const RayShear shear(ray.direction);
            const PacketRay packet_ray = make_packet_ray(ray, shear);
            for (std::size_t start = 0; start < triangles.size(); start += width) {
                // Packed here, not by pack_triangles (the other exercise): lane l of vertex v on
                // axis a at (3 v + a) width + l.
                for (int lane = 0; lane < width; ++lane) {
                    lanes[lane] = static_cast<std::uint32_t>(start + lane);
                    const ch06::TriangleVertices& t = triangles[lanes[lane]];
                    const Vec3 corners[3] = {t.p0, t.p1, t.p2};
                    for (int vertex = 0; vertex < 3; ++vertex)
                        for (int axis = 0; axis < 3; ++axis)
                            coordinates[(3 * vertex + axis) * width + lane] = corners[vertex][axis];
                }
                kernel.test(packet_ray, coordinates.data(), first_lanes(static_cast<std::uint32_t>(width)), hits);
                for (int lane = 0; lane < width; ++lane) {
                    if ((hits.edge_lanes >> lane) & 1u) continue;  // the scalar test's to decide
                    const ch06::TriangleVertices& t = triangles[lanes[lane]];
                    const auto expected = intersect_triangle(ray, shear, t.p0, t.p1, t.p2);
                    const bool hit = (hits.hit_lanes >> lane) & 1u;
                    const bool agree = hit == expected.has_value() &&
                                       (!hit || std::bit_cast<std::uint32_t>(hits.t[lane]) ==
                                                    std::bit_cast<std::uint32_t>(expected->t));
                    if (!agree && mismatches++ == 0)
                        first = "triangle " + std::to_string(lanes[lane]) + ": scalar " + (expected ? "hit" : "miss") +
                                ", kernel " + (hit ? "hit" : "miss");
                    if (hit) {
                        ++hits_seen;
                        both_windings |= 1 << (lanes[lane] % 2);
                    }
                }
            }
        }
        INFO(kernel.instructions << " (width " << width << "): " << mismatches << " lanes differ; first: " << first);
        CHECK(mismatches == 0);
        CHECK(hits_seen > 100);
        CHECK(both_windings == 3);  // hits on triangles of either winding were compared
    }
}
