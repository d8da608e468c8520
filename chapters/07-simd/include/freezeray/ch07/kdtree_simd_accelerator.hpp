// The vectorised KD-tree (`--accel kdtree-simd`): chapter 06's tree and walk, its leaves repacked
// into packets of W triangles tested at once (packet_kernel.hpp); the hits are kdtree's, which
// are bruteforce's, to the bit.
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/ch06/kdtree_accelerator.hpp"
#include "freezeray/ch07/kdtree_simd_settings.hpp"
#include "freezeray/ch07/packet_kernels.hpp"
#include "freezeray/ch07/triangle_packets.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace freezeray::ch07 {

class KdTreeSimdAccelerator final : public Accelerator, public ch06::CountedTraversal {
public:
    explicit KdTreeSimdAccelerator(const KdTreeSimdSettings& settings = {});

    void build(const std::vector<TriangleMesh>& meshes) override;
    // As KdTreeAccelerator: the same triangle, the same t bits.
    std::optional<Hit> intersect(const Ray& ray) const override;
    bool occluded(const Ray& ray) const override;
    // occluded's walk, hits on triangles whose flag is clear looked through.
    bool occluded_by(const Ray& ray, const TriangleFlags& counted) const override;
    // What intersect(ray) does, counted; a packet tested counts as one triangle test.
    ch06::TraversalCounts count_traversal(const Ray& ray) const override;

    std::vector<std::pair<std::string, std::string>> describe() const override;
    std::optional<std::size_t> memory_bytes() const override;

    const PacketKernel& kernel() const { return *kernel_; }
    const TrianglePackets& packets() const { return packets_; }
    // Milliseconds spent repacking, after the tree's own build.
    double packing_milliseconds() const { return packing_milliseconds_; }

private:
    template <typename Counter>
    std::optional<Hit> closest_hit(const Ray& ray, Counter& counter) const;
    // occluded and occluded_by: whether a hit on a triangle for which counts(global index)
    // holds blocks the ray.
    template <typename Counts>
    bool any_hit(const Ray& ray, Counts&& counts) const;

    KdTreeSimdSettings settings_;
    const PacketKernel* kernel_;
    ch06::KdTreeAccelerator scalar_;  // the tree, and the answers kdtree gives
    TrianglePackets packets_;
    double packing_milliseconds_ = 0.0;
};

}  // namespace freezeray::ch07
