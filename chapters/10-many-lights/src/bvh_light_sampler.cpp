// The light BVH: its build by a surface area and orientation heuristic, and the walk that samples
// a light and the one that gives a light's probability (book chapter 10; Conty Estevez and Kulla
// 2018, sections 4.2-4.4; pbrt-v4, section 12.6.3).
#include "freezeray/ch10/bvh_light_sampler.hpp"

#include "freezeray/ch06/surface_area_heuristic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace freezeray::ch10 {

namespace {

constexpr int Buckets = 12;
// Below this depth the build splits by cost; deeper, at the median, so that a path from the root
// always fits the 64 bits of a TreePath.
constexpr int CostSplitDepth = 48;

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
    paths_.resize(lights.size());
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
    if (!entries.empty()) build(entries, 0, entries.size(), 0, 0);
    // pbrt-v4's rule: the tree counts as one more infinite light, chosen as often as each of them.
    const auto infinite = static_cast<float>(infinite_lights_.size());
    infinite_probability_ = infinite > 0.0f ? infinite / (infinite + (nodes_.empty() ? 0.0f : 1.0f)) : 0.0f;
    build_milliseconds_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

LightBounds BvhLightSampler::build(std::vector<Entry>& entries, std::size_t begin, std::size_t end, std::uint64_t bits, int depth) {
    max_depth_ = std::max(max_depth_, depth);
    if (end - begin == 1) {
        nodes_.push_back({LightCluster(entries[begin].bounds), entries[begin].light, true});
        node_bounds_.push_back(entries[begin].bounds);
        paths_[entries[begin].light] = {bits, depth};
        return entries[begin].bounds;
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
    const std::size_t index = nodes_.size();
    nodes_.push_back({});
    node_bounds_.emplace_back();
    const LightBounds first = build(entries, begin, middle, bits, depth + 1);
    nodes_[index].second_child_or_light = static_cast<std::uint32_t>(nodes_.size());
    const LightBounds second = build(entries, middle, end, bits | (std::uint64_t{1} << depth), depth + 1);
    const LightBounds bounds = bounds_union(first, second);
    nodes_[index].cluster = LightCluster(bounds);
    node_bounds_[index] = bounds;
    return bounds;
}

// BOOK(bvh-sample)
std::optional<LightChoice> BvhLightSampler::sample(const ShadingPoint& point, float u) const {
    if (u < infinite_probability_) {  // a light beside the tree
        const std::size_t n = infinite_lights_.size();
        const std::size_t i = std::min(static_cast<std::size_t>(u / infinite_probability_ * static_cast<float>(n)), n - 1);
        return LightChoice{infinite_lights_[i], infinite_probability_ / static_cast<float>(n)};
    }
    // EXERCISE(ch10/tree-walk): the walk of book chapter 10, "The walk and its probability", as sample's comment in bvh_light_sampler.hpp states it: u rescaled to the tree's share, one child at each interior node in proportion to child_probabilities, u reused, the probability multiplied from the root down; nothing where no child can send light, and a tree of one light chosen only where it can
    if (nodes_.empty()) return std::nullopt;
    u = std::min((u - infinite_probability_) / (1.0f - infinite_probability_), OneMinusEpsilon);
    float probability = 1.0f - infinite_probability_;
    std::uint32_t index = 0;
    while (!nodes_[index].is_leaf) {
        // Down to one child, chosen in proportion to its importance; u is reused, rescaled.
        const LightTreeNode& node = nodes_[index];
        const std::uint32_t children[2] = {index + 1, node.second_child_or_light};
        const std::array<float, 2> p = child_probabilities(nodes_[children[0]], nodes_[children[1]], point);
        if (p[0] < 0.0f) return std::nullopt;  // no light below sends light here
        const int child = u < p[0] ? 0 : 1;
        u = child == 0 ? u / p[0] : (u - p[0]) / p[1];
        u = std::min(u, OneMinusEpsilon);
        probability *= p[child];
        index = children[child];
    }
    // A tree of one light: its own importance was never looked at.
    if (index == 0 && importance(nodes_[0].cluster, point) <= 0.0f) return std::nullopt;
    return LightChoice{lights_[nodes_[index].second_child_or_light].get(), probability};
    // END EXERCISE
}
// END BOOK

// BOOK(bvh-probability)
float BvhLightSampler::probability(const ShadingPoint& point, const Light& light) const {
    // EXERCISE(ch10/tree-path-probability): the probability that sample() chooses `light` at `point`, as book chapter 10, "The walk and its probability", derives it: for a light beside the tree its share of infinite_probability_; for one in the tree, the walk along its recorded path (paths_) multiplying the probabilities of the children taken; 0 where sample() could never reach it
    if (light.index >= paths_.size()) return 0.0f;
    if (is_infinite_[light.index]) return infinite_probability_ / static_cast<float>(infinite_lights_.size());
    const TreePath& path = paths_[light.index];
    if (path.depth < 0) return 0.0f;
    float probability = 1.0f - infinite_probability_;
    std::uint32_t index = 0;
    for (int depth = 0; depth < path.depth; ++depth) {
        const LightTreeNode& node = nodes_[index];
        const std::uint32_t children[2] = {index + 1, node.second_child_or_light};
        const std::array<float, 2> p = child_probabilities(nodes_[children[0]], nodes_[children[1]], point);
        if (p[0] < 0.0f) return 0.0f;
        const int child = static_cast<int>((path.bits >> depth) & 1u);
        probability *= p[child];
        index = children[child];
    }
    if (index == 0 && importance(nodes_[0].cluster, point) <= 0.0f) return 0.0f;
    return probability;
    // END EXERCISE
}
// END BOOK

std::vector<std::string> BvhLightSampler::description() const {
    char line[256];
    std::vector<std::string> lines;
    const std::size_t in_tree = (nodes_.size() + 1) / 2;
    std::snprintf(line, sizeof line, "tree: %zu lights, %zu nodes, depth %d, %.1f KiB, built in %.2f ms", in_tree, nodes_.size(),
                  max_depth_, static_cast<double>(nodes_.size() * sizeof(LightTreeNode)) / 1024.0, build_milliseconds_);
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
