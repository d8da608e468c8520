// What a KD-tree build made: its size, its shape and how long it took.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace freezeray::ch06 {

struct KdTreeStatistics {
    double build_milliseconds = 0.0;
    int build_threads = 1;                // threads that built subtrees (the first one included)
    std::size_t triangles = 0;            // given to the build
    std::size_t skipped_triangles = 0;    // with a non-finite vertex: no ray can hit them, no cell holds them
    std::size_t nodes = 0;
    std::size_t leaves = 0;
    std::size_t empty_leaves = 0;
    std::size_t triangle_references = 0;  // entries in all leaves: a triangle a plane cuts is in several
    int depth_limit = 0;                  // the maximum depth the build allowed
    int max_depth = 0;                    // the deepest leaf's
    double mean_leaf_depth = 0.0;
    double mean_triangles_per_leaf = 0.0;  // over the leaves that hold triangles
    std::size_t memory_bytes = 0;          // nodes, leaf lists, triangle vertices and ids

    // Name and value pairs for printing ("nodes", "12345 (6172 leaves, 1230 empty)").
    std::vector<std::pair<std::string, std::string>> describe() const;
};

}  // namespace freezeray::ch06
