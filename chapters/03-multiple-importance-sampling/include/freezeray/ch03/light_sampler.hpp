// Choosing which light to sample: in proportion to each light's power, so bright lights get
// most of the samples, or uniformly (for comparison; pbrt-v3, section 14.3.3).
#pragma once

#include "freezeray/light.hpp"
#include "freezeray/ch03/piecewise_constant.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace freezeray::ch03 {

enum class LightSelection { Power, Uniform };

class LightSampler {
public:
    LightSampler(const std::vector<std::unique_ptr<Light>>& lights, LightSelection selection);

    struct Choice {
        const Light* light;
        float probability;
    };
    // One light chosen with u in [0, 1); nothing when the scene has no light.
    std::optional<Choice> sample(float u) const;
    // The probability that sample() chooses this light.
    float probability(const Light& light) const;

private:
    const std::vector<std::unique_ptr<Light>>& lights_;
    PiecewiseConstant1D distribution_;
};

}  // namespace freezeray::ch03
