// The KD-tree's settings: the costs of the surface area heuristic and the limits of the build.
#pragma once

#include "freezeray/parameters.hpp"

#include <cstddef>

namespace freezeray::ch06 {

// The traversal keeps a fixed stack of the far children still to visit; a tree never grows
// deeper than it, since each level pushes at most one entry.
inline constexpr int TraversalStackSize = 64;

struct KdTreeSettings {
    // The costs of the surface area heuristic (MacDonald and Booth, "Heuristics for ray tracing
    // using space subdivision", 1990): one step through an interior node and one ray-triangle
    // test, in the same unit; only their ratio and the bonus shape the tree. pbrt-v3's values
    // (KdTreeAccel's defaults): on Crytek Sponza they built a tree of 1.2 million nodes in half
    // the time of Wald and Havran's K_T = 15, K_I = 20, lambda = 0.8 (4.4 million nodes), which
    // traced rays no faster.
    float traversal_cost = 1.0f;
    float intersection_cost = 80.0f;
    // The fraction of the intersection cost a split saves when one child is empty (pbrt-v3's
    // emptyBonus; Wald and Havran 2006 write the factor lambda = 1 - bonus).
    float empty_bonus = 0.5f;
    // The depth at which every node becomes a leaf; 0: automatic, round(8 + 1.3 log2 N) for N
    // triangles (pbrt-v3, section 4.4.2), at most TraversalStackSize; N / triangles_per_test
    // when triangles are tested several at a time.
    int max_depth = 0;
    // A node with at most this many triangles becomes a leaf without a split being tried
    // (pbrt-v3's maxPrims). 0 leaves every decision to the cost model, as in Wald and Havran.
    int leaf_size = 1;
    // A split whose cost is not lower than the leaf's is still made while fewer than this many
    // such splits lie above the node (pbrt-v3's badRefines allow 2): a first split that does not
    // pay may let its children's splits pay.
    int max_unproductive_refinements = 2;
    // Threads the build may use; 0: one per core. The tree does not depend on it.
    int build_threads = 0;
    // The triangles one intersection test handles: 1 in this chapter. Chapter 07 tests packets of
    // W triangles at once; a node of n triangles then costs ceil(n / W) tests, and the tree it
    // builds has leaves that fill their packets. Not a key of the scene's block: chapter 07 sets it.
    int triangles_per_test = 1;
};

// The maximum depth the build uses for n triangles: the setting, or the automatic one, never
// more than TraversalStackSize.
int effective_max_depth(const KdTreeSettings& settings, std::size_t triangle_count);

// Reads the settings from a JSON object (missing keys keep their defaults): traversal_cost,
// intersection_cost (both > 0), empty_bonus (in [0, 1)), max_depth (0 to 64), leaf_size (>= 0),
// max_unproductive_refinements (>= 0), build_threads (0 to 256). Errors name the JSON path.
KdTreeSettings read_kdtree_settings(const Parameters& parameters);

}  // namespace freezeray::ch06
