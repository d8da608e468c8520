// Repacking chapter 06's leaves into packets of W triangles, structure of arrays.
#include "freezeray/ch07/triangle_packets.hpp"

#include "freezeray/ch07/packet_ray.hpp"

#include <algorithm>
#include <stdexcept>

namespace freezeray::ch07 {

// BOOK(pack-triangles)
void pack_triangles(const std::vector<ch06::TriangleVertices>& vertices, const std::uint32_t* leaf_triangles,
                    int count, int width, float* coordinates, std::uint32_t* lanes) {
    // EXERCISE(ch07/structure-of-arrays): write the leaf's triangles into the packet in structure-of-arrays layout, book chapter 07, "Structure of arrays"; the layout and the padding lanes as pack_triangles' comment in triangle_packets.hpp and packet_floats state them
    for (int lane = 0; lane < width; ++lane) {
        const std::uint32_t triangle = leaf_triangles[lane < count ? lane : count - 1];
        lanes[lane] = triangle;
        const ch06::TriangleVertices& t = vertices[triangle];
        const Vec3* corners[3] = {&t.p0, &t.p1, &t.p2};
        for (int vertex = 0; vertex < 3; ++vertex)
            for (int axis = 0; axis < 3; ++axis) coordinates[(3 * vertex + axis) * width + lane] = (*corners[vertex])[axis];
    }
    // END EXERCISE
}
// END BOOK

TrianglePackets::TrianglePackets(const ch06::KdTree& tree, const std::vector<ch06::TriangleVertices>& vertices,
                                 int width)
    : width_(width), floats_(packet_floats(width)) {
    if (width < 1 || width > MaxLanes) throw std::invalid_argument("packet width must be 1 to 16");
    tree_.bounds = tree.bounds;
    tree_.nodes = tree.nodes;
    // Count the packets first, so that the arrays are allocated once.
    std::size_t packets = 0;
    for (const ch06::KdTreeNode& node : tree.nodes)
        if (node.is_leaf()) packets += (node.triangle_count() + width - 1) / width;
    coordinates_.assign(packets * floats_, 0.0f);
    lanes_.assign(packets * width, 0u);

    std::uint32_t next = 0;
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        // The triangles from chapter 06's node; the copy's node then points at the packets.
        const ch06::KdTreeNode& leaf = tree.nodes[i];
        if (!leaf.is_leaf()) continue;
        const std::uint32_t count = leaf.triangle_count();
        const std::uint32_t* list = ch06::leaf_triangle_list(tree, leaf);
        tree_.nodes[i] = ch06::KdTreeNode::leaf(count, next);
        for (std::uint32_t first = 0; first < count; first += width, ++next) {
            const int in_packet = static_cast<int>(std::min<std::uint32_t>(width, count - first));
            pack_triangles(vertices, list + first, in_packet, width, coordinates_.data() + std::size_t(next) * floats_,
                           lanes_.data() + std::size_t(next) * width);
        }
        triangles_ += count;
    }
}

double TrianglePackets::lane_occupancy() const {
    return lanes_.empty() ? 1.0 : static_cast<double>(triangles_) / static_cast<double>(lanes_.size());
}

std::size_t TrianglePackets::memory_bytes() const {
    return tree_.nodes.size() * sizeof(ch06::KdTreeNode) + coordinates_.size() * sizeof(float) +
           lanes_.size() * sizeof(std::uint32_t);
}

}  // namespace freezeray::ch07
