// A blend of two BSDFs, e.g. a metal with patches of paint: f = (1 - weight) f_first + weight f_second.
#pragma once

#include "freezeray/bsdf.hpp"

namespace freezeray::ch02 {

// weight in [0, 1] is both the blend weight of `second` and the probability of sampling it. The
// two BSDFs must outlive this one (they live in the same ScratchArena).
class MixBSDF final : public BSDF {
public:
    MixBSDF(const BSDF* first, const BSDF* second, float weight) : first_(first), second_(second), weight_(weight) {}

    Spectrum eval(const Vec3& wo, const Vec3& wi) const override;
    std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const override;
    float pdf(const Vec3& wo, const Vec3& wi) const override;
    std::uint32_t flags() const override;

private:
    const BSDF* first_;
    const BSDF* second_;
    float weight_;
};

}  // namespace freezeray::ch02
