// The KD-tree as it is stored for traversal: 8-byte nodes in depth-first order and one array of
// the triangles of the leaves (pbrt-v3, section 4.4.1, "Tree Representation").
#pragma once

#include "freezeray/math.hpp"

#include <bit>
#include <cstdint>
#include <vector>

namespace freezeray::ch06 {

// BOOK(kdtree-node)
// One node in 8 bytes. The low 2 bits of `flags` say what it is: 0, 1, 2 an interior node
// splitting along x, y or z, 3 a leaf; the other 30 bits hold the index of the above child (an
// interior node: its below child comes right after it) or the leaf's triangle count. `payload`
// holds the split position's bits (interior), the one triangle of a one-triangle leaf, or the
// offset of the leaf's triangles in KdTree::leaf_triangles.
class KdTreeNode {
public:
    static constexpr std::uint32_t LeafFlag = 3;
    static constexpr std::uint32_t MaxIndex = (1u << 30) - 1;  // above-child index or leaf count

    static KdTreeNode interior(int axis, float split, std::uint32_t above_child) {
        return KdTreeNode(std::bit_cast<std::uint32_t>(split), (above_child << 2) | static_cast<std::uint32_t>(axis));
    }
    // A one-triangle leaf keeps its triangle inline; a longer one, its offset in leaf_triangles.
    static KdTreeNode leaf(std::uint32_t triangle_count, std::uint32_t triangle_or_offset) {
        return KdTreeNode(triangle_or_offset, (triangle_count << 2) | LeafFlag);
    }

    bool is_leaf() const { return (flags_ & 3u) == LeafFlag; }
    int split_axis() const { return static_cast<int>(flags_ & 3u); }
    float split_position() const { return std::bit_cast<float>(payload_); }
    std::uint32_t above_child() const { return flags_ >> 2; }
    std::uint32_t triangle_count() const { return flags_ >> 2; }
    std::uint32_t one_triangle() const { return payload_; }
    // The one triangle of a one-triangle leaf, as a list of one (see leaf_triangle_list).
    const std::uint32_t* one_triangle_list() const { return &payload_; }
    std::uint32_t triangle_offset() const { return payload_; }

    // Sets an interior node's above child once the below subtree is written.
    void set_above_child(std::uint32_t index) { flags_ = (index << 2) | (flags_ & 3u); }

    bool operator==(const KdTreeNode&) const = default;

private:
    KdTreeNode(std::uint32_t payload, std::uint32_t flags) : payload_(payload), flags_(flags) {}

    std::uint32_t payload_;
    std::uint32_t flags_;
};

static_assert(sizeof(KdTreeNode) == 8, "a node is 8 bytes (pbrt-v3's KdAccelNode)");
// END BOOK

// A triangle's three vertices, copied from its mesh so that a leaf's triangles are read from one
// array (the same floats, so the same intersections as from the mesh).
struct TriangleVertices {
    Vec3 p0, p1, p2;
};

// Where a global triangle comes from: its mesh and its index there.
struct TriangleId {
    std::uint32_t mesh, triangle;
};

// The tree: node 0 is the root, whose cell is `bounds`. Triangles are global indices (the
// triangles of all meshes numbered in mesh order, then triangle order).
struct KdTree {
    Bounds3 bounds;
    std::vector<KdTreeNode> nodes;
    std::vector<std::uint32_t> leaf_triangles;
};

// A leaf's triangle_count() triangles: the one kept in the node, or its list in leaf_triangles.
inline const std::uint32_t* leaf_triangle_list(const KdTree& tree, const KdTreeNode& leaf) {
    return leaf.triangle_count() == 1 ? leaf.one_triangle_list() : tree.leaf_triangles.data() + leaf.triangle_offset();
}

}  // namespace freezeray::ch06
