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

// One node: the bounds of its lights, as the walk reads them; a leaf holds one light, an interior
// node's first child follows it, its second is at `second_child_or_light`.
struct LightTreeNode {
    LightCluster cluster;
    std::uint32_t second_child_or_light = 0;
    bool is_leaf = false;
};

// The probabilities of going to each child of an interior node from `point` (light_bounds.hpp).
inline std::array<float, 2> child_probabilities(const LightTreeNode& first, const LightTreeNode& second, const ShadingPoint& point) {
    return child_probabilities(first.cluster, second.cluster, point);
}

class BvhLightSampler final : public LightSampler {
public:
    explicit BvhLightSampler(const std::vector<std::unique_ptr<Light>>& lights);

    // A light beside the tree with probability infinite_probability(); otherwise u, rescaled to
    // [0, 1), walks the tree from the root: at each interior node it goes to one child with the
    // probabilities of child_probabilities, u rescaled to [0, 1) again within the child's share,
    // and the choice's probability is 1 - infinite_probability() times the probabilities of the
    // children taken, multiplied from the root down (so that probability() gives the same float).
    // Nothing where neither child of a node can send light to the point.
    std::optional<LightChoice> sample(const ShadingPoint& point, float u) const override;
    float probability(const ShadingPoint& point, const Light& light) const override;
    std::vector<std::string> description() const override;

    const std::vector<LightTreeNode>& nodes() const { return nodes_; }
    // The bounds each node's cluster was made from, by node (for tests and inspection; the walk
    // reads only the clusters).
    const std::vector<LightBounds>& node_bounds() const { return node_bounds_; }
    // Lights chosen beside the tree (environment and directional lights), each with probability
    // infinite_probability() / their count, wherever the point is.
    const std::vector<const Light*>& infinite_lights() const { return infinite_lights_; }
    float infinite_probability() const { return infinite_probability_; }

private:
    // Where a light sits in the tree: the choices (bit d: second child at depth d) from the root.
    struct TreePath {
        std::uint64_t bits = 0;
        int depth = -1;  // -1: not in the tree (beside it, or sending no light)
    };
    struct Entry {
        LightBounds bounds;
        std::uint32_t light;
    };
    // Builds the subtree of entries [begin, end) and returns the bounds of all its lights.
    LightBounds build(std::vector<Entry>& entries, std::size_t begin, std::size_t end, std::uint64_t bits, int depth);

    const std::vector<std::unique_ptr<Light>>& lights_;
    std::vector<LightTreeNode> nodes_;
    std::vector<LightBounds> node_bounds_;
    std::vector<TreePath> paths_;  // by Light::index
    std::vector<const Light*> infinite_lights_;
    std::vector<bool> is_infinite_;  // by Light::index
    float infinite_probability_ = 0.0f;
    int max_depth_ = 0;
    double build_milliseconds_ = 0.0;
    std::size_t dark_lights_ = 0;  // zero power: never chosen
};

}  // namespace freezeray::ch10
