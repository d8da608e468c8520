// Chapter 06's leaves repacked for the vector test: each leaf's triangles in packets of W lanes,
// structure of arrays (packet_ray.hpp), the last packet of a leaf padded.
#pragma once

#include "freezeray/cache_line_allocator.hpp"
#include "freezeray/ch06/kdtree_node.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace freezeray::ch07 {

// Writes the triangles `leaf_triangles` (global indices into `vertices`, at most `width` of them)
// into one packet: `coordinates` (9 width floats, see packet_floats) and `lanes` (width global
// indices). Padding lanes repeat the last triangle; the traversal masks them off.
void pack_triangles(const std::vector<ch06::TriangleVertices>& vertices, const std::uint32_t* leaf_triangles,
                    int count, int width, float* coordinates, std::uint32_t* lanes);

class TrianglePackets {
public:
    TrianglePackets() = default;
    // Repacks every leaf of `tree` into packets of `width` lanes (1, 4, 8 or 16).
    TrianglePackets(const ch06::KdTree& tree, const std::vector<ch06::TriangleVertices>& vertices, int width);

    int width() const { return width_; }
    // The tree's bounds and nodes, its leaves now holding the index of their first packet
    // (triangle_offset) and still their triangle count; no leaf_triangles.
    const ch06::KdTree& tree() const { return tree_; }
    const float* coordinates(std::uint32_t packet) const { return coordinates_.data() + std::size_t(packet) * floats_; }
    const std::uint32_t* lanes(std::uint32_t packet) const { return lanes_.data() + std::size_t(packet) * width_; }

    std::size_t packet_count() const { return lanes_.size() / (width_ > 0 ? width_ : 1); }
    std::size_t triangle_count() const { return triangles_; }
    // The share of lanes that hold a triangle (the rest is padding).
    double lane_occupancy() const;
    // Nodes, coordinates and lanes.
    std::size_t memory_bytes() const;

private:
    int width_ = 0;
    int floats_ = 0;
    ch06::KdTree tree_;
    std::vector<float, CacheLineAllocator<float>> coordinates_;
    std::vector<std::uint32_t> lanes_;
    std::size_t triangles_ = 0;
};

}  // namespace freezeray::ch07
