// The settings of the vectorised KD-tree: chapter 06's tree, and the packet width.
#pragma once

#include "freezeray/ch06/kdtree_settings.hpp"
#include "freezeray/parameters.hpp"

namespace freezeray::ch07 {

struct KdTreeSimdSettings {
    ch06::KdTreeSettings tree;  // the same build as `kdtree`, so the same tree
    // Triangles per packet: 1, 4, 8 or 16, or 0 for the widest this processor runs.
    int simd_width = 0;
    // What the surface area heuristic charges a leaf of n triangles: ceil(n / W) packet tests
    // (true, the default: the build fills packets), or n triangle tests as in chapter 06 (false:
    // chapter 06's very tree, repacked).
    bool packet_leaf_cost = true;
};

// Reads the kdtree keys (read_kdtree_settings), simd_width and simd_leaf_cost ("packets" or
// "triangles"); a width this build or processor
// cannot run is an InputError at its JSON path (or flag).
KdTreeSimdSettings read_kdtree_simd_settings(const Parameters& parameters);

}  // namespace freezeray::ch07
