// Sorting a batch's rays by direction octant and origin (see ray_order.hpp).
#include "ray_order.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace freezeray::benchmark {

namespace {

// The 10 bits of v spread to every third bit: bit k goes to bit 3k.
std::uint32_t spread_bits(std::uint32_t v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

// Where x lies in [low, high], in 1024 steps (0 for a flat extent or a point outside).
std::uint32_t quantize(float x, float low, float high) {
    const float extent = high - low;
    if (!(extent > 0.0f)) return 0;
    const float cell = std::floor((x - low) / extent * 1024.0f);
    return static_cast<std::uint32_t>(std::clamp(cell, 0.0f, 1023.0f));
}

}  // namespace

std::uint32_t morton_code(const Vec3& point, const Bounds3& bounds) {
    return (spread_bits(quantize(point.z, bounds.min.z, bounds.max.z)) << 2) |
           (spread_bits(quantize(point.y, bounds.min.y, bounds.max.y)) << 1) |
           spread_bits(quantize(point.x, bounds.min.x, bounds.max.x));
}

void sort_for_coherence(RayBatches& batches, const Bounds3& bounds) {
    for (std::vector<Ray>& batch : batches.rays) {
        // The key: octant in bits 30 to 32, Morton code below.
        std::vector<std::pair<std::uint64_t, std::size_t>> keys(batch.size());
        for (std::size_t i = 0; i < batch.size(); ++i) {
            const Vec3& d = batch[i].direction;
            const std::uint64_t octant = (d.x < 0.0f ? 4u : 0u) | (d.y < 0.0f ? 2u : 0u) | (d.z < 0.0f ? 1u : 0u);
            keys[i] = {(octant << 30) | morton_code(batch[i].origin, bounds), i};
        }
        std::stable_sort(keys.begin(), keys.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<Ray> sorted;
        sorted.reserve(batch.size());
        for (const auto& key : keys) sorted.push_back(batch[key.second]);
        batch = std::move(sorted);
    }
}

}  // namespace freezeray::benchmark
