// Choosing which light to sample, the same way at every shading point: in proportion to each
// light's power, so bright lights get most of the samples, or uniformly (for comparison; pbrt-v3,
// section 14.3.3). Registered as the light samplers `power` and `uniform`; chapter 10 adds one
// that looks at the shading point.
#pragma once

#include "freezeray/light.hpp"
#include "freezeray/light_sampler.hpp"
#include "freezeray/ch03/piecewise_constant.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace freezeray::ch03 {

enum class LightSelection { Power, Uniform };

class FixedLightSampler final : public LightSampler {
public:
    FixedLightSampler(const std::vector<std::unique_ptr<Light>>& lights, LightSelection selection);

    using Choice = LightChoice;
    // One light chosen with u in [0, 1); nothing when the scene has no light.
    std::optional<LightChoice> sample(float u) const;
    // The probability that sample() chooses this light.
    float probability(const Light& light) const;

    // The same wherever the point is.
    std::optional<LightChoice> sample(const ShadingPoint&, float u) const override { return sample(u); }
    float probability(const ShadingPoint&, const Light& light) const override { return probability(light); }
    std::vector<std::string> description() const override;

private:
    const std::vector<std::unique_ptr<Light>>& lights_;
    LightSelection selection_;
    PiecewiseConstant1D distribution_;  // the choice by power (one zero weight for the uniform choice)
};

}  // namespace freezeray::ch03
