// The vectorised KD-tree's build and queries: chapter 06's walk (kdtree_traversal.hpp), a packet
// test per leaf packet instead of a triangle test per triangle, and chapter 06's rule for which
// of the hits brute force would report.
#include "freezeray/ch07/kdtree_simd_accelerator.hpp"

#include "freezeray/close_hits.hpp"
#include "freezeray/ch06/kdtree_traversal.hpp"
#include "freezeray/triangle_intersection.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <limits>

namespace freezeray::ch07 {

namespace {

// BOOK(packet-hits)
// Calls on_hit(global triangle, TriangleHit) for each triangle of a leaf the ray hits, packet by
// packet and in lane order. The kernel decides most lanes; a lane on an edge is decided by the
// scalar test, in double precision where it must be, with its tie-breaking rule. `ray.tmax` is
// read before each packet, so on_hit may shorten it. on_hit returns false to stop. `counter` is
// told of each packet tested.
template <typename Counter, typename OnHit>
void for_each_hit_in_leaf(const TrianglePackets& packets, PacketTest test_packet,
                          const std::vector<ch06::TriangleVertices>& vertices, const ch06::KdTreeNode& leaf,
                          const Ray& ray, const RayShear& shear, PacketRay& packet_ray, Counter& counter, OnHit&& on_hit) {
    const std::uint32_t width = static_cast<std::uint32_t>(packets.width());
    const std::uint32_t count = leaf.triangle_count();
    std::uint32_t packet = leaf.triangle_offset();
    PacketHits hits;
    for (std::uint32_t first = 0; first < count; first += width, ++packet) {
        packet_ray.tmax = ray.tmax;
        counter.test();
        test_packet(packet_ray, packets.coordinates(packet), first_lanes(std::min(width, count - first)), hits);
        const std::uint32_t* lanes = packets.lanes(packet);
        for (std::uint32_t remaining = hits.hit_lanes | hits.edge_lanes; remaining != 0; remaining &= remaining - 1) {
            const int lane = std::countr_zero(remaining);
            const std::uint32_t triangle = lanes[lane];
            std::optional<TriangleHit> hit;
            if ((hits.edge_lanes >> lane) & 1u) {
                const ch06::TriangleVertices& v = vertices[triangle];
                hit = intersect_triangle(ray, shear, v.p0, v.p1, v.p2);
            } else {
                hit = TriangleHit{hits.t[lane], hits.b0[lane], hits.b1[lane], hits.b2[lane]};
            }
            if (hit && !on_hit(triangle, *hit)) return;
        }
    }
}
// END BOOK

}  // namespace

KdTreeSimdAccelerator::KdTreeSimdAccelerator(const KdTreeSimdSettings& settings)
    : settings_(settings),
      kernel_(settings.simd_width == 0 ? &widest_kernel() : &kernel_of_width(settings.simd_width, "simd_width")),
      scalar_([&] {
          ch06::KdTreeSettings tree = settings.tree;
          tree.triangles_per_test = settings.packet_leaf_cost ? kernel_->width : 1;
          return tree;
      }()) {}

void KdTreeSimdAccelerator::build(const std::vector<TriangleMesh>& meshes) {
    scalar_.build(meshes);
    const auto start = std::chrono::steady_clock::now();
    packets_ = TrianglePackets(scalar_.tree(), scalar_.triangle_vertices(), kernel_->width);
    packing_milliseconds_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// BOOK(kdtree-simd-intersect)
template <typename Counter>
std::optional<Hit> KdTreeSimdAccelerator::closest_hit(const Ray& ray, Counter& counter) const {
    const std::optional<ch06::Walk> walk = ch06::start_walk(packets_.tree(), ray);
    if (!walk) return std::nullopt;
    const RayShear shear(ray.direction);
    PacketRay packet_ray = make_packet_ray(ray, shear);
    Ray test = ray;  // its tmax shrinks to just beyond the closest hit so far
    CloseHits close;
    ch06::traverse(packets_.tree(), ray, *walk, counter, [&](const ch06::KdTreeNode& leaf) {
        for_each_hit_in_leaf(packets_, kernel_->test, scalar_.triangle_vertices(), leaf, test, shear, packet_ray, counter,
                             [&](std::uint32_t triangle, const TriangleHit& hit) {
                                 close.add(triangle, hit);
                                 test.tmax = std::min(ray.tmax, close.limit() * ch06::TieLimitFactor);
                                 return true;
                             });
        return close.limit();
    });
    return scalar_.brute_force_answer(ray, *walk, shear, close);
}
// END BOOK

std::optional<Hit> KdTreeSimdAccelerator::intersect(const Ray& ray) const {
    ch06::NoCounting counter;
    return closest_hit(ray, counter);
}

ch06::TraversalCounts KdTreeSimdAccelerator::count_traversal(const Ray& ray) const {
    ch06::TraversalCounts counts;
    ch06::Counting counter{counts};
    closest_hit(ray, counter);
    return counts;
}

template <typename Counts>
bool KdTreeSimdAccelerator::any_hit(const Ray& ray, Counts&& counts) const {
    const std::optional<ch06::Walk> walk = ch06::start_walk(packets_.tree(), ray);
    if (!walk) return false;
    const RayShear shear(ray.direction);
    PacketRay packet_ray = make_packet_ray(ray, shear);
    bool found = false;
    ch06::NoCounting counter;
    ch06::traverse(packets_.tree(), ray, *walk, counter, [&](const ch06::KdTreeNode& leaf) {
        for_each_hit_in_leaf(packets_, kernel_->test, scalar_.triangle_vertices(), leaf, ray, shear, packet_ray, counter,
                             [&](std::uint32_t triangle, const TriangleHit&) {
                                 found = counts(triangle) && scalar_.blocks(ray, *walk, triangle);
                                 return !found;  // the first blocking hit answers the question
                             });
        return found ? -std::numeric_limits<float>::infinity() : ray.tmax;
    });
    return found;
}

bool KdTreeSimdAccelerator::occluded(const Ray& ray) const {
    return any_hit(ray, [](std::uint32_t) { return true; });
}

bool KdTreeSimdAccelerator::occluded_by(const Ray& ray, const TriangleFlags& counted) const {
    return any_hit(ray, [&](std::uint32_t triangle) { return scalar_.flagged(counted, triangle); });
}

std::vector<std::pair<std::string, std::string>> KdTreeSimdAccelerator::describe() const {
    char occupancy[64], packing[64];
    std::snprintf(occupancy, sizeof occupancy, "%.1f %%", 100.0 * packets_.lane_occupancy());
    std::snprintf(packing, sizeof packing, "%.1f", packing_milliseconds_);
    std::vector<std::pair<std::string, std::string>> lines{
        {"kind", "kdtree-simd (the kdtree's leaves in packets, one ray against W triangles at once)"},
        {"simd width", std::to_string(kernel_->width) + " (" + kernel_->instructions + ", " +
                           (settings_.simd_width == 0 ? "the widest this processor runs" : "as asked") + ")"},
        {"packets", std::to_string(packets_.packet_count())},
        {"lanes used", occupancy},
        {"packing ms", packing}};
    char memory[64];
    std::snprintf(memory, sizeof memory, "%.2f MB (the tree's and the packets')",
                  static_cast<double>(memory_bytes().value_or(0)) / (1024.0 * 1024.0));
    for (auto& line : scalar_.describe()) {
        if (line.first == "kind") continue;
        if (line.first == "memory") line.second = memory;
        lines.push_back(std::move(line));
    }
    return lines;
}

std::optional<std::size_t> KdTreeSimdAccelerator::memory_bytes() const {
    return scalar_.memory_bytes().value_or(0) + packets_.memory_bytes();
}

}  // namespace freezeray::ch07
