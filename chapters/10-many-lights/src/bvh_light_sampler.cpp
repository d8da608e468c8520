// The light BVH: its build by a surface area and orientation heuristic, and the walk that samples
// a light and the one that gives a light's probability (book chapter 10; Conty Estevez and Kulla
// 2018, sections 4.2-4.4; pbrt-v4, section 12.6.3).
#include "freezeray/ch10/bvh_light_sampler.hpp"

#include "freezeray/ch06/surface_area_heuristic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace freezeray::ch10 {

namespace {

constexpr int Buckets = 12;
// Below this depth the build splits by cost; deeper, at the median, so that no tree is deeper
// than MaxDepth (with at most 2^32 lights).
constexpr int CostSplitDepth = 48;
constexpr int MaxDepth = CostSplitDepth + 32;

Vec3 centre(const Bounds3& b) { return (b.min + b.max) * 0.5f; }

int widest_axis(const Vec3& extent) { return extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2; }

// BOOK(light-split-cost)
// The cost of a cluster in a split along `axis` of a node whose box is `node_box`: its power,
// times the solid angle its emission cone spans (M_Omega), times its surface area, times a factor
// that discourages thin slabs (Conty Estevez and Kulla 2018, equation 9; pbrt-v4's EvaluateCost).
double cluster_cost(const LightBounds& b, const Bounds3& node_box, int axis) {
    const double theta_o = std::acos(std::clamp(static_cast<double>(b.cos_theta_o), -1.0, 1.0));
    const double theta_e = std::acos(std::clamp(static_cast<double>(b.cos_theta_e), -1.0, 1.0));
    const double theta_w = std::min(theta_o + theta_e, static_cast<double>(Pi));
    const double sin_o = std::sin(theta_o), cos_o = std::cos(theta_o);
    const double m_omega = 2.0 * Pi * (1.0 - cos_o) +
                           Pi / 2.0 * (2.0 * theta_w * sin_o - std::cos(theta_o - 2.0 * theta_w) - 2.0 * theta_o * sin_o + cos_o);
    const Vec3 diagonal = node_box.diagonal();
    const double regularity = static_cast<double>(max_component(diagonal)) / static_cast<double>(diagonal[axis]);
    return static_cast<double>(b.phi) * m_omega * regularity * ch06::surface_area(b.box);
}
// END BOOK

}  // namespace

BvhLightSampler::BvhLightSampler(const std::vector<std::unique_ptr<Light>>& lights) : lights_(lights) {
    const auto start = std::chrono::steady_clock::now();
    is_infinite_.assign(lights.size(), false);
    std::vector<Entry> entries;
    for (const auto& light : lights) {
        const std::optional<LightBounds> bounds = bounds_of(*light);
        if (!bounds) {
            infinite_lights_.push_back(light.get());
            is_infinite_[light->index] = true;
        } else if (bounds->phi > 0.0f && std::isfinite(bounds->phi)) {
            entries.push_back({*bounds, light->index});
        } else {
            ++dark_lights_;  // sends no light: never chosen, and nothing is lost
        }
    }
    light_slots_.assign(lights.size(), Slot{NotInTree, 0});
    if (!entries.empty()) {
        // A node names a light by its index with LightBit set: every index must stay below it.
        if (lights.size() > LightTreeNode::LightBit) throw std::length_error("light BVH: more than 2^31 lights");
        std::vector<BinaryNode> binary;
        binary.reserve(2 * entries.size() - 1);
        const std::uint32_t root = build_binary(entries, 0, entries.size(), 0, binary);
        nodes_.emplace_back();
        node_bounds_.emplace_back();
        node_slots_.push_back({NotInTree, 0});
        gather(binary, root, 0, 0);
    }
    // pbrt-v4's rule: the tree counts as one more infinite light, chosen as often as each of them.
    const auto infinite = static_cast<float>(infinite_lights_.size());
    infinite_probability_ = infinite > 0.0f ? infinite / (infinite + (nodes_.empty() ? 0.0f : 1.0f)) : 0.0f;
    build_milliseconds_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::uint32_t BvhLightSampler::build_binary(std::vector<Entry>& entries, std::size_t begin, std::size_t end, int depth,
                                            std::vector<BinaryNode>& binary) {
    if (end - begin == 1) {
        BinaryNode leaf;
        leaf.bounds = entries[begin].bounds;
        leaf.light = entries[begin].light;
        leaf.is_leaf = true;
        binary.push_back(leaf);
        return static_cast<std::uint32_t>(binary.size() - 1);
    }
    Bounds3 node_box, centres;
    for (std::size_t i = begin; i < end; ++i) {
        node_box.expand(entries[i].bounds.box);
        centres.expand(centre(entries[i].bounds.box));
    }
    // The cheapest split between buckets of the lights' centres, over the three axes.
    double best_cost = INFINITY;
    int best_axis = -1, best_bucket = -1;
    auto bucket_of = [&](const Entry& e, int axis) {
        const float extent = centres.max[axis] - centres.min[axis];
        const int b = static_cast<int>(Buckets * ((centre(e.bounds.box)[axis] - centres.min[axis]) / extent));
        return std::clamp(b, 0, Buckets - 1);
    };
    for (int axis = 0; axis < 3 && depth < CostSplitDepth; ++axis) {
        if (!(centres.max[axis] > centres.min[axis])) continue;
        LightBounds bucket[Buckets];
        std::size_t count[Buckets] = {};
        for (std::size_t i = begin; i < end; ++i) {
            const int b = bucket_of(entries[i], axis);
            bucket[b] = count[b] == 0 ? entries[i].bounds : bounds_union(bucket[b], entries[i].bounds);
            ++count[b];
        }
        for (int split = 0; split < Buckets - 1; ++split) {
            LightBounds below, above;
            std::size_t n_below = 0, n_above = 0;
            for (int b = 0; b <= split; ++b)
                if (count[b] > 0) below = n_below++ == 0 ? bucket[b] : bounds_union(below, bucket[b]);
            for (int b = split + 1; b < Buckets; ++b)
                if (count[b] > 0) above = n_above++ == 0 ? bucket[b] : bounds_union(above, bucket[b]);
            if (n_below == 0 || n_above == 0) continue;
            const double cost = cluster_cost(below, node_box, axis) + cluster_cost(above, node_box, axis);
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best_bucket = split;
            }
        }
    }
    std::size_t middle;
    if (best_axis >= 0) {
        middle = static_cast<std::size_t>(
            std::partition(entries.begin() + static_cast<std::ptrdiff_t>(begin), entries.begin() + static_cast<std::ptrdiff_t>(end),
                           [&](const Entry& e) { return bucket_of(e, best_axis) <= best_bucket; }) -
            entries.begin());
    } else {
        // Every centre in one place (or too deep): halve by count along the widest axis.
        const int axis = widest_axis(centres.diagonal());
        middle = begin + (end - begin) / 2;
        std::nth_element(entries.begin() + static_cast<std::ptrdiff_t>(begin), entries.begin() + static_cast<std::ptrdiff_t>(middle),
                         entries.begin() + static_cast<std::ptrdiff_t>(end), [axis](const Entry& a, const Entry& b) {
                             const float ca = centre(a.bounds.box)[axis], cb = centre(b.bounds.box)[axis];
                             return ca != cb ? ca < cb : a.light < b.light;
                         });
    }
    BinaryNode node;
    node.children[0] = build_binary(entries, begin, middle, depth + 1, binary);
    node.children[1] = build_binary(entries, middle, end, depth + 1, binary);
    node.bounds = bounds_union(binary[node.children[0]].bounds, binary[node.children[1]].bounds);
    node.light_count = binary[node.children[0]].light_count + binary[node.children[1]].light_count;
    binary.push_back(node);
    return static_cast<std::uint32_t>(binary.size() - 1);
}

// BOOK(light-tree-gather)
void BvhLightSampler::gather(const std::vector<BinaryNode>& binary, std::uint32_t b, std::uint32_t at, int depth) {
    node_bounds_[at] = binary[b].bounds;
    // Its two children, then the one among them with the most lights replaced by its own two (in
    // place, so that the children keep the binary tree's order), until there are enough: the
    // largest subtrees are flattened first, so that no light is left deep down.
    std::uint32_t group[LightTreeWidth] = {b};
    int count = 1;
    if (!binary[b].is_leaf) {
        group[0] = binary[b].children[0];
        group[1] = binary[b].children[1];
        count = 2;
    }
    while (count < LightTreeWidth) {
        int open = -1;
        for (int i = 0; i < count; ++i)
            if (!binary[group[i]].is_leaf && (open < 0 || binary[group[i]].light_count > binary[group[open]].light_count)) open = i;
        if (open < 0) break;  // only leaves
        const BinaryNode& opened = binary[group[open]];
        std::copy_backward(group + open + 1, group + count, group + count + 1);
        group[open] = opened.children[0];
        group[open + 1] = opened.children[1];
        ++count;
    }
    nodes_[at].child_count = static_cast<std::uint32_t>(count);
    for (int i = 0; i < count; ++i) {
        const BinaryNode& child = binary[group[i]];
        nodes_[at].children.set(i, child.bounds);
        if (child.is_leaf) {
            nodes_[at].child[i] = child.light | LightTreeNode::LightBit;
            light_slots_[child.light] = {at, static_cast<std::uint32_t>(i)};
            max_depth_ = std::max(max_depth_, depth + 1);
            continue;
        }
        const auto index = static_cast<std::uint32_t>(nodes_.size());
        nodes_[at].child[i] = index;
        nodes_.emplace_back();
        node_bounds_.emplace_back();
        node_slots_.push_back({at, static_cast<std::uint32_t>(i)});
        gather(binary, group[i], index, depth + 1);
    }
}
// END BOOK

// BOOK(child-probabilities)
ChildWeights child_weights(const LightTreeNode& node, const ShadingPoint& point) {
    static_assert(LightTreeWidth == 4, "the sum below adds four lanes");
    Lanes weight = importance(node.children, point);
    // A glossy lobe at the point: each cluster as the lobe sees it (never 0 where the importance
    // is not: the lobe only prefers, it never leaves a light out).
    if (point.lobe_alpha > 0.0f)
        weight = select(weight > 0.0f, max(weight * lobe_factor(node.children, point), splat(std::numeric_limits<float>::min())), splat(0.0f));
    weight *= 1.0f / LightTreeWidth;
    return {weight, (weight[0] + weight[1]) + (weight[2] + weight[3])};
}

ChildProbabilities child_probabilities(const ChildWeights& weights) {
    ChildProbabilities p;
    if (!(weights.sum > 0.0f)) {
        p.fill(-1.0f);
        return p;
    }
    const Lanes shares = weights.weight / weights.sum;
    for (int i = 0; i < LightTreeWidth; ++i) p[static_cast<std::size_t>(i)] = shares[i];
    return p;
}
// END BOOK

// BOOK(bvh-sample)
std::optional<LightChoice> BvhLightSampler::sample(const ShadingPoint& point, float u) const {
    if (u < infinite_probability_) {  // a light beside the tree
        const std::size_t n = infinite_lights_.size();
        const std::size_t i = std::min(static_cast<std::size_t>(u / infinite_probability_ * static_cast<float>(n)), n - 1);
        return LightChoice{infinite_lights_[i], infinite_probability_ / static_cast<float>(n)};
    }
    // EXERCISE(ch10/tree-walk): the walk of book chapter 10, "The walk and its probability", as sample's comment in bvh_light_sampler.hpp states it: u rescaled to the tree's share, at each node the child whose share of [0, 1) holds u (the weights of child_weights laid end to end, over their sum), u reused, the probability multiplied from the root down; nothing where no child can send light, and a tree of one light chosen only where it can
    if (nodes_.empty()) return std::nullopt;
    u = std::min((u - infinite_probability_) / (1.0f - infinite_probability_), OneMinusEpsilon);
    float probability = 1.0f - infinite_probability_;
    std::uint32_t index = 0;
    for (;;) {
        // Down to the child whose share of [0, 1) holds u; u is reused, rescaled within it.
        const LightTreeNode& node = nodes_[index];
        const ChildWeights w = child_weights(node, point);
        if (!(w.sum > 0.0f)) return std::nullopt;  // no light below sends light here
        const ChildProbabilities p = child_probabilities(w);
        // The shares are compared as weights with u times their sum, so that the choice does not
        // wait for the divisions that give the probabilities.
        const float target = u * w.sum;
        int child = 0;
        float share_start = 0.0f, share_end = 0.0f;
        for (int i = 0; i < static_cast<int>(node.child_count); ++i) {
            if (p[static_cast<std::size_t>(i)] == 0.0f) continue;  // no share: never taken
            child = i;
            share_start = share_end;
            share_end += w.weight[i];
            if (target < share_end) break;
        }
        u = std::min((target - share_start) / w.weight[child], OneMinusEpsilon);
        probability *= p[static_cast<std::size_t>(child)];
        if (node.child_is_light(child)) return LightChoice{lights_[node.child_index(child)].get(), probability};
        index = node.child_index(child);
    }
    // END EXERCISE
}
// END BOOK

// BOOK(bvh-probability)
float BvhLightSampler::probability(const ShadingPoint& point, const Light& light) const {
    // EXERCISE(ch10/tree-path-probability): the probability that sample() chooses `light` at `point`, as book chapter 10, "The walk and its probability", derives it: for a light beside the tree its share of infinite_probability_; for one in the tree, the walk from the root down to its leaf (light_slots_, and node_slots_ to find the way) multiplying the probabilities of the children taken, in sample()'s order; 0 where sample() could never reach it
    if (light.index >= light_slots_.size()) return 0.0f;
    if (is_infinite_[light.index]) return infinite_probability_ / static_cast<float>(infinite_lights_.size());
    if (light_slots_[light.index].node == NotInTree) return 0.0f;
    // The slots on the way from the root to the light, found from the light up.
    Slot path[MaxDepth + 1];
    int depth = 0;
    for (Slot slot = light_slots_[light.index]; slot.node != NotInTree; slot = node_slots_[slot.node]) path[depth++] = slot;
    // Down again, multiplying the same probabilities in the same order as sample().
    float probability = 1.0f - infinite_probability_;
    while (depth > 0) {
        const Slot& slot = path[--depth];
        const ChildProbabilities p = child_probabilities(nodes_[slot.node], point);
        if (p[0] < 0.0f) return 0.0f;
        probability *= p[slot.lane];
    }
    return probability;
    // END EXERCISE
}
// END BOOK

std::vector<std::string> BvhLightSampler::description() const {
    char line[256];
    std::vector<std::string> lines;
    const auto in_tree = static_cast<std::size_t>(std::count_if(light_slots_.begin(), light_slots_.end(), [](const Slot& s) { return s.node != NotInTree; }));
    std::snprintf(line, sizeof line, "tree: %zu lights, %zu nodes of up to %d children, depth %d, %.1f KiB, built in %.2f ms", in_tree,
                  nodes_.size(), LightTreeWidth, max_depth_, static_cast<double>(nodes_.size() * sizeof(LightTreeNode)) / 1024.0,
                  build_milliseconds_);
    lines.emplace_back(line);
    if (!infinite_lights_.empty()) {
        std::snprintf(line, sizeof line, "beside the tree: %zu environment or directional lights, chosen with probability %.3g",
                      infinite_lights_.size(), static_cast<double>(infinite_probability_));
        lines.emplace_back(line);
    }
    if (dark_lights_ > 0) {
        std::snprintf(line, sizeof line, "%zu lights send no light and are never chosen", dark_lights_);
        lines.emplace_back(line);
    }
    return lines;
}

}  // namespace freezeray::ch10
