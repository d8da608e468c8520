// The light BVH: a tree over the scene's lights whose every node bounds what its lights can send,
// walked from the root towards the lights that matter for the shading point (book chapter 10;
// Conty Estevez and Kulla, "Importance Sampling of Many Lights with Adaptive Tree Splitting",
// 2018; pbrt-v4's BVHLightSampler, Pharr, Jakob and Humphreys 2023, section 12.6.3).
#pragma once

#include "freezeray/ch10/light_bounds.hpp"
#include "freezeray/light_sampler.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace freezeray::ch10 {

// BOOK(light-tree-node)
// The most children a node has: one per lane, so that their importances are computed at once.
// The build makes a binary tree and then gathers each node's descendants up to this many into
// one node (book chapter 10, "A wider tree").
inline constexpr int LightTreeWidth = LaneCount;

// One node: the bounds of its children, lane by lane, and what they are: child[i] is the index of
// a node, or of a light (Light::index) with LightBit set. Lanes from child_count on are empty.
struct LightTreeNode {
    static constexpr std::uint32_t LightBit = 0x80000000u;

    LightClusterGroup children;
    std::uint32_t child[LightTreeWidth] = {};
    std::uint32_t child_count = 0;

    bool child_is_light(int i) const { return (child[i] & LightBit) != 0; }
    std::uint32_t child_index(int i) const { return child[i] & ~LightBit; }
};
// END BOOK

// The weights of a node's children at `point`: their importances divided by the width, so that
// their sum stays finite even when each is the largest float (0 in empty lanes); and that sum.
struct ChildWeights {
    Lanes weight;
    float sum;
};
ChildWeights child_weights(const LightTreeNode& node, const ShadingPoint& point);

// The probabilities of going to each child of a node: weight / sum, 0 in empty lanes; all -1
// when no child can send light there (the sum is 0).
using ChildProbabilities = std::array<float, LightTreeWidth>;
ChildProbabilities child_probabilities(const ChildWeights& weights);
inline ChildProbabilities child_probabilities(const LightTreeNode& node, const ShadingPoint& point) {
    return child_probabilities(child_weights(node, point));
}

class BvhLightSampler final : public LightSampler {
public:
    explicit BvhLightSampler(const std::vector<std::unique_ptr<Light>>& lights);

    // A light beside the tree with probability infinite_probability(); otherwise u, rescaled to
    // [0, 1), walks the tree from the root: at each node it goes to the child whose share of
    // [0, 1) holds u, the shares being the children's weights (child_weights) laid end to end in
    // their order, over their sum (a child whose probability is 0 has none; a u that rounding
    // leaves past them all goes to the last child that has one), u rescaled to [0, 1) again
    // within that share; the choice's probability is 1 - infinite_probability() times the
    // child_probabilities of the children taken, multiplied from the root down (so that
    // probability() gives the same float). Nothing where no child of a node can send light to
    // the point.
    std::optional<LightChoice> sample(const ShadingPoint& point, float u) const override;
    float probability(const ShadingPoint& point, const Light& light) const override;
    std::vector<std::string> description() const override;

    const std::vector<LightTreeNode>& nodes() const { return nodes_; }
    // The bounds of all the lights below each node, by node (for tests and inspection; the walk
    // reads only the children's bounds).
    const std::vector<LightBounds>& node_bounds() const { return node_bounds_; }
    // Lights chosen beside the tree (environment and directional lights), each with probability
    // infinite_probability() / their count, wherever the point is.
    const std::vector<const Light*>& infinite_lights() const { return infinite_lights_; }
    float infinite_probability() const { return infinite_probability_; }

private:
    struct Entry {
        LightBounds bounds;
        std::uint32_t light;
    };
    static constexpr std::uint32_t NotInTree = 0xffffffffu;
    // A node of the binary tree the build makes first.
    struct BinaryNode {
        LightBounds bounds;
        std::uint32_t children[2] = {0, 0};
        std::uint32_t light = 0;        // a leaf's light (Light::index)
        std::uint32_t light_count = 1;  // the lights in its subtree
        bool is_leaf = false;
    };
    // Builds the binary subtree of entries [begin, end) into `binary`; returns its root's index.
    std::uint32_t build_binary(std::vector<Entry>& entries, std::size_t begin, std::size_t end, int depth,
                               std::vector<BinaryNode>& binary);
    // Writes binary node `b` as nodes_[at] (a leaf as a node of one child, for a tree of one
    // light): its children are its descendants, opened from the one with the most lights down
    // until there are LightTreeWidth of them (or only leaves).
    void gather(const std::vector<BinaryNode>& binary, std::uint32_t b, std::uint32_t at, int depth);

    // Where a node or a light hangs in the tree: its parent node and the lane it has there.
    struct Slot {
        std::uint32_t node, lane;
    };

    const std::vector<std::unique_ptr<Light>>& lights_;
    std::vector<LightTreeNode> nodes_;
    std::vector<LightBounds> node_bounds_;
    std::vector<Slot> node_slots_;   // by node; the root's node is NotInTree
    std::vector<Slot> light_slots_;  // by Light::index; NotInTree for a light not in the tree
    std::vector<const Light*> infinite_lights_;
    std::vector<bool> is_infinite_;  // by Light::index
    float infinite_probability_ = 0.0f;
    int max_depth_ = 0;
    double build_milliseconds_ = 0.0;
    std::size_t dark_lights_ = 0;  // zero power: never chosen
};

}  // namespace freezeray::ch10
