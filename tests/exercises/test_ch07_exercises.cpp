// Grading tests of chapter 07's exercises. Each calls its exercise's own code first (so that in a
// student copy it fails through its own stub) and checks it against exact answers: the packet
// layout float by float, the inside mask against the scalar test's sign rule on every
// combination of signs (through a lane type of the test's own), and the kernels' hits against
// the scalar watertight test bit by bit. Deterministic: no statistical test in this file.
#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/ch07/packet_kernel.hpp"
#include "freezeray/ch07/packet_kernels.hpp"
#include "freezeray/ch07/triangle_packets.hpp"
#include "freezeray/random.hpp"
#include "freezeray/triangle_intersection.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
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

namespace {

// Four lanes of plain floats, with every operation inside_lanes may use (packet_kernel.hpp lists
// them; those the solution does not use are maybe_unused): the test's own lane type, so that the
// exercise is checked without the kernels.
struct FourMask {
    std::array<bool, 4> lane;
    static FourMask all() { return {{true, true, true, true}}; }
};
[[maybe_unused]] FourMask operator&(FourMask a, FourMask b) { return {{a.lane[0] && b.lane[0], a.lane[1] && b.lane[1], a.lane[2] && b.lane[2], a.lane[3] && b.lane[3]}}; }
[[maybe_unused]] FourMask operator|(FourMask a, FourMask b) { return {{a.lane[0] || b.lane[0], a.lane[1] || b.lane[1], a.lane[2] || b.lane[2], a.lane[3] || b.lane[3]}}; }
[[maybe_unused]] FourMask and_not(FourMask a, FourMask b) { return {{a.lane[0] && !b.lane[0], a.lane[1] && !b.lane[1], a.lane[2] && !b.lane[2], a.lane[3] && !b.lane[3]}}; }
std::uint32_t bits(FourMask m) {
    std::uint32_t b = 0;
    for (int i = 0; i < 4; ++i) b |= static_cast<std::uint32_t>(m.lane[static_cast<std::size_t>(i)]) << i;
    return b;
}

struct FourLanes {
    using Mask = FourMask;
    static constexpr int width = 4;
    std::array<float, 4> value;
    static FourLanes load(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
    static FourLanes broadcast(float x) { return {{x, x, x, x}}; }
    void store(float* p) const { std::copy(value.begin(), value.end(), p); }
};
template <typename Compare>
FourMask compare(FourLanes a, FourLanes b, Compare c) {
    return {{c(a.value[0], b.value[0]), c(a.value[1], b.value[1]), c(a.value[2], b.value[2]), c(a.value[3], b.value[3])}};
}
template <typename Operation>
FourLanes apply(FourLanes a, FourLanes b, Operation o) {
    return {{o(a.value[0], b.value[0]), o(a.value[1], b.value[1]), o(a.value[2], b.value[2]), o(a.value[3], b.value[3])}};
}
[[maybe_unused]] FourLanes operator+(FourLanes a, FourLanes b) { return apply(a, b, std::plus<float>()); }
[[maybe_unused]] FourLanes operator-(FourLanes a, FourLanes b) { return apply(a, b, std::minus<float>()); }
[[maybe_unused]] FourLanes operator*(FourLanes a, FourLanes b) { return apply(a, b, std::multiplies<float>()); }
[[maybe_unused]] FourLanes operator/(FourLanes a, FourLanes b) { return apply(a, b, std::divides<float>()); }
[[maybe_unused]] FourLanes abs(FourLanes a) { return apply(a, a, [](float x, float) { return std::fabs(x); }); }
[[maybe_unused]] FourLanes max(FourLanes a, FourLanes b) { return apply(a, b, [](float x, float y) { return std::max(x, y); }); }
[[maybe_unused]] FourMask operator<(FourLanes a, FourLanes b) { return compare(a, b, std::less<float>()); }
[[maybe_unused]] FourMask operator<=(FourLanes a, FourLanes b) { return compare(a, b, std::less_equal<float>()); }
[[maybe_unused]] FourMask operator>(FourLanes a, FourLanes b) { return compare(a, b, std::greater<float>()); }
[[maybe_unused]] FourMask operator>=(FourLanes a, FourLanes b) { return compare(a, b, std::greater_equal<float>()); }
[[maybe_unused]] FourMask operator==(FourLanes a, FourLanes b) { return compare(a, b, std::equal_to<float>()); }

}  // namespace

TEST_CASE("ch07/inside-mask", "[exercise]") {
    // Every combination of signs for u, v and w, four at a time in four lanes, against the scalar
    // test's rule (intersect_triangle): outside when some edge function is negative and some
    // positive; zeros of either sign, tiny and infinite values included.
    const float values[] = {-3.0f, -1e-30f, -0.0f, 0.0f, 1e-30f, 2.0f, -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::infinity()};
    std::vector<std::array<float, 3>> triples;
    for (const float u : values)
        for (const float v : values)
            for (const float w : values) triples.push_back({u, v, w});
    int inside = 0;
    for (std::size_t first = 0; first < triples.size(); first += 4) {
        FourLanes u{}, v{}, w{};
        std::uint32_t expected = 0;
        for (std::size_t lane = 0; lane < 4; ++lane) {
            const auto& [a, b, c] = triples[first + lane];
            u.value[lane] = a;
            v.value[lane] = b;
            w.value[lane] = c;
            const bool outside = (a < 0.0f || b < 0.0f || c < 0.0f) && (a > 0.0f || b > 0.0f || c > 0.0f);
            expected |= static_cast<std::uint32_t>(!outside) << lane;
        }
        const std::uint32_t found = bits(inside_lanes<FourLanes, FourMask>(u, v, w));
        INFO("lanes (u, v, w): (" << u.value[0] << ", " << v.value[0] << ", " << w.value[0] << "), (" << u.value[1] << ", "
                                  << v.value[1] << ", " << w.value[1] << "), (" << u.value[2] << ", " << v.value[2] << ", "
                                  << w.value[2] << "), (" << u.value[3] << ", " << v.value[3] << ", " << w.value[3] << ")");
        REQUIRE(found == expected);
        inside += std::popcount(expected);
    }
    CHECK(inside == 5 * 5 * 5 + 5 * 5 * 5 - 2 * 2 * 2);  // all >= 0 or all <= 0 (both zeros in both)
}

namespace {

// The scalar test's edge functions in single precision, as intersect_triangle computes them
// before it decides anything: a lane is an edge lane when one of them is exactly zero.
bool on_edge_in_float(const Ray& ray, const RayShear& shear, const ch06::TriangleVertices& t) {
    const Vec3 a = t.p0 - ray.origin, b = t.p1 - ray.origin, c = t.p2 - ray.origin;
    const float ax = a[shear.kx] - shear.sx * a[shear.kz], ay = a[shear.ky] - shear.sy * a[shear.kz];
    const float bx = b[shear.kx] - shear.sx * b[shear.kz], by = b[shear.ky] - shear.sy * b[shear.kz];
    const float cx = c[shear.kx] - shear.sx * c[shear.kz], cy = c[shear.ky] - shear.sy * c[shear.kz];
    return cx * by - cy * bx == 0.0f || ax * cy - ay * cx == 0.0f || bx * ay - by * ax == 0.0f;
}

// A triangle the ray crosses well inside, at t = 1.5 (for the padding lanes: a kernel that
// reports padding would report it).
ch06::TriangleVertices crossed_triangle(const Ray& ray) {
    const Vec3 d = ray.direction;
    const Vec3 a = glm::normalize(std::abs(d.x) < 0.6f ? glm::cross(d, Vec3(1, 0, 0)) : glm::cross(d, Vec3(0, 1, 0)));
    const Vec3 b = glm::cross(d, a);
    const Vec3 p = ray.origin + 1.5f * d;
    return {p + 2.0f * a, p - a + 1.7f * b, p - a - 1.7f * b};
}

struct KernelTally {
    int lanes = 0, hits = 0, edge_lanes = 0, padded_crossed = 0, mismatches = 0;
    std::string first;
};

// One packet: `triangles` in the first `valid` lanes, the rest padding holding a triangle the ray
// crosses; the kernel's answer against the scalar test's, lane by lane.
void compare_packet(const PacketKernel& kernel, const Ray& ray, const std::vector<ch06::TriangleVertices>& triangles,
                    int valid, KernelTally& tally) {
    const int width = kernel.width;
    const RayShear shear(ray.direction);
    std::vector<float, CacheLineAllocator<float>> coordinates(packet_floats(width));
    const ch06::TriangleVertices padding = crossed_triangle(ray);
    for (int lane = 0; lane < width; ++lane) {
        const ch06::TriangleVertices& t = lane < valid ? triangles[static_cast<std::size_t>(lane)] : padding;
        const Vec3 corners[3] = {t.p0, t.p1, t.p2};
        for (int vertex = 0; vertex < 3; ++vertex)
            for (int axis = 0; axis < 3; ++axis) coordinates[(3 * vertex + axis) * width + lane] = corners[vertex][axis];
    }
    PacketHits hits;
    hits.hit_lanes = hits.edge_lanes = 0xdeadbeefu;  // whatever was there before
    kernel.test(make_packet_ray(ray, shear), coordinates.data(), first_lanes(static_cast<std::uint32_t>(valid)), hits);

    auto mismatch = [&](const std::string& what) {
        if (tally.mismatches++ == 0) tally.first = what;
    };
    const std::uint32_t valid_mask = first_lanes(static_cast<std::uint32_t>(valid));
    if ((hits.hit_lanes | hits.edge_lanes) & ~valid_mask) mismatch("a padding lane (" + std::to_string(valid) + " of " + std::to_string(width) + " valid) is reported");
    if (hits.hit_lanes & hits.edge_lanes) mismatch("a lane is both a hit and an edge lane");
    if (valid < width) tally.padded_crossed += intersect_triangle(ray, shear, padding.p0, padding.p1, padding.p2).has_value();
    for (int lane = 0; lane < valid; ++lane) {
        const ch06::TriangleVertices& t = triangles[static_cast<std::size_t>(lane)];
        const std::string where = "lane " + std::to_string(lane) + " of " + std::to_string(width) + ": ";
        ++tally.lanes;
        const bool edge = on_edge_in_float(ray, shear, t);
        const bool reported_edge = (hits.edge_lanes >> lane) & 1u, hit = (hits.hit_lanes >> lane) & 1u;
        if (reported_edge != edge) {
            mismatch(where + (edge ? "an edge function is exactly 0, not reported as an edge lane" : "reported as an edge lane, no edge function is 0"));
            continue;
        }
        if (edge) {
            ++tally.edge_lanes;
            continue;  // the scalar test's to decide
        }
        const std::optional<TriangleHit> expected = intersect_triangle(ray, shear, t.p0, t.p1, t.p2);
        if (hit != expected.has_value()) {
            mismatch(where + "the scalar test " + (expected ? "hits" : "misses") + ", the kernel " + (hit ? "hits" : "misses"));
            continue;
        }
        if (!hit) continue;
        ++tally.hits;
        const float found[4] = {hits.t[lane], hits.b0[lane], hits.b1[lane], hits.b2[lane]};
        const float wanted[4] = {expected->t, expected->b0, expected->b1, expected->b2};
        const char* names[4] = {"t", "b0", "b1", "b2"};
        for (int k = 0; k < 4; ++k)
            if (std::bit_cast<std::uint32_t>(found[k]) != std::bit_cast<std::uint32_t>(wanted[k])) {
                mismatch(where + names[k] + " " + std::to_string(found[k]) + " differs from the scalar test's " +
                         std::to_string(wanted[k]) + " in its bits");
                break;
            }
    }
}

}  // namespace

TEST_CASE("ch07/packet-kernel", "[exercise]") {
    // Every kernel this processor runs, narrowest (scalar) first, against intersect_triangle lane
    // by lane: the edge lanes exactly where a single-precision edge function is 0, then hit or
    // not and t, b0, b1, b2 to the bit; padding lanes (which hold a triangle the ray crosses)
    // never reported; a lane never both a hit and an edge lane.
    PCG32 random(77, 7);
    auto point = [&] { return Vec3(random.next_float(), random.next_float(), random.next_float()) * 2.0f - 1.0f; };

    // 1. Random triangles of both windings, rays at random points, through vertices and edges,
    //    and leaving a triangle from a point on it (t near 0, which the conservative bound must
    //    reject), with a random tmax.
    std::vector<ch06::TriangleVertices> soup;
    for (int i = 0; i < 64; ++i) {
        ch06::TriangleVertices t{point(), point(), point()};
        if (i % 2) std::swap(t.p1, t.p2);
        soup.push_back(t);
    }
    std::vector<Ray> rays;
    for (int i = 0; i < 500; ++i) {
        const ch06::TriangleVertices& t = soup[static_cast<std::size_t>(i) % soup.size()];
        Vec3 origin = point() * 3.0f, target = point() * 0.5f;
        if (i % 5 == 1) target = t.p0;                               // a vertex
        if (i % 5 == 2) target = 0.5f * (t.p1 + t.p2);               // an edge
        if (i % 5 == 3) origin = (t.p0 + t.p1 + t.p2) / 3.0f;        // leaving the triangle itself
        Ray ray{origin, glm::normalize(target - origin + (i % 5 == 3 ? point() : Vec3(0.0f)))};
        if (i % 3 == 0) ray.tmax = 0.5f + 3.0f * random.next_float();
        rays.push_back(ray);
    }
    // 2. A floor of integer squares, each cut in two, and rays straight down (and along a
    //    diagonal) through integer and half-integer points: edge functions exactly 0 on shared
    //    edges and vertices.
    std::vector<ch06::TriangleVertices> grid;
    for (int x = -2; x < 2; ++x)
        for (int y = -2; y < 2; ++y) {
            const Vec3 p00(x, y, 0), p10(x + 1, y, 0), p01(x, y + 1, 0), p11(x + 1, y + 1, 0);
            grid.push_back({p00, p10, p11});
            grid.push_back({p00, p11, p01});
        }
    std::vector<Ray> grid_rays;
    for (int i = -4; i <= 4; ++i)
        for (int j = -4; j <= 4; ++j) {
            const Vec3 above(0.5f * i, 0.5f * j, 2.0f);
            grid_rays.push_back(Ray{above, Vec3(0, 0, -1)});
            grid_rays.push_back(Ray{above + Vec3(1, 1, 0), glm::normalize(Vec3(-0.5f, -0.5f, -1.0f))});
        }

    int kernels = 0;
    for (const PacketKernel& kernel : built_kernels()) {
        if (!cpu_runs(kernel)) continue;
        ++kernels;
        const int width = kernel.width;
        KernelTally tally;
        auto run = [&](const std::vector<Ray>& ray_set, const std::vector<ch06::TriangleVertices>& triangles) {
            for (const Ray& ray : ray_set)
                for (std::size_t start = 0; start < triangles.size(); start += static_cast<std::size_t>(width)) {
                    // Full packets, and packets with 1 to W - 1 valid lanes.
                    const int valid = width == 1 || random.next_below(3) != 0 ? width
                                                                               : 1 + static_cast<int>(random.next_below(static_cast<std::uint32_t>(width - 1)));
                    std::vector<ch06::TriangleVertices> packet;
                    for (int lane = 0; lane < valid; ++lane) packet.push_back(triangles[(start + static_cast<std::size_t>(lane)) % triangles.size()]);
                    compare_packet(kernel, ray, packet, valid, tally);
                }
        };
        run(rays, soup);
        run(grid_rays, grid);
        INFO(kernel.instructions << " (width " << width << "): " << tally.mismatches << " of " << tally.lanes
                                 << " lanes differ from the scalar test; first: " << tally.first);
        CHECK(tally.mismatches == 0);
        CHECK(tally.hits > 1000);       // the comparison is not empty
        CHECK(tally.edge_lanes > 50);   // edge lanes occurred
        if (width > 1) CHECK(tally.padded_crossed > 100);  // padding a wrong mask would report
    }
    CHECK(kernels >= 1);
}
