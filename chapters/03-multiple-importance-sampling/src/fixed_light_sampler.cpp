// Light selection by power (pbrt-v3, section 14.3.3).
#include "freezeray/ch03/fixed_light_sampler.hpp"

#include <algorithm>

namespace freezeray::ch03 {

namespace {

// The power of each light, the weights of the choice by power. A light with zero power is never
// chosen by power (it would only waste shadow rays); when every light has zero power the
// distribution falls back to uniform, and the image is black.
std::vector<float> power_weights(const std::vector<std::unique_ptr<Light>>& lights) {
    std::vector<float> weights;
    weights.reserve(lights.size());
    for (const auto& light : lights) weights.push_back(luminance(light->power()));
    return weights;
}

}  // namespace

FixedLightSampler::FixedLightSampler(const std::vector<std::unique_ptr<Light>>& lights, LightSelection selection)
    : lights_(lights),
      selection_(selection),
      // The uniform choice needs no table (see sample); the power choice searches this one.
      distribution_(lights.empty() || selection == LightSelection::Uniform ? std::vector<float>{0.0f}
                                                                            : power_weights(lights)) {}

std::optional<LightChoice> FixedLightSampler::sample(float u) const {
    if (lights_.empty()) return std::nullopt;
    if (selection_ == LightSelection::Uniform) {
        // Every light equally: the index is u scaled, with no table to search (a binary search
        // over thousands of equal steps costs a mispredicted branch per step).
        const std::size_t n = lights_.size();
        const std::size_t i = std::min(static_cast<std::size_t>(u * static_cast<float>(n)), n - 1);
        return LightChoice{lights_[i].get(), 1.0f / static_cast<float>(n)};
    }
    const std::size_t i = distribution_.sample_discrete(u);
    return LightChoice{lights_[i].get(), distribution_.discrete_probability(i)};
}

float FixedLightSampler::probability(const Light& light) const {
    if (lights_.empty()) return 0.0f;
    if (selection_ == LightSelection::Uniform) return 1.0f / static_cast<float>(lights_.size());
    return distribution_.discrete_probability(light.index);
}

std::vector<std::string> FixedLightSampler::description() const {
    return {selection_ == LightSelection::Power ? "in proportion to power, the same at every point"
                                                : "uniformly, the same at every point"};
}

}  // namespace freezeray::ch03
