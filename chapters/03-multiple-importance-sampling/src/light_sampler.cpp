// Light selection by power (pbrt-v3, section 14.3.3).
#include "freezeray/ch03/light_sampler.hpp"

namespace freezeray::ch03 {

namespace {

std::vector<float> selection_weights(const std::vector<std::unique_ptr<Light>>& lights, LightSelection selection) {
    std::vector<float> weights;
    weights.reserve(lights.size());
    // A light with zero power is never chosen by power (it would only waste shadow rays); when
    // every light has zero power the distribution falls back to uniform, and the image is black.
    for (const auto& light : lights) weights.push_back(selection == LightSelection::Power ? luminance(light->power()) : 1.0f);
    return weights;
}

}  // namespace

LightSampler::LightSampler(const std::vector<std::unique_ptr<Light>>& lights, LightSelection selection)
    : lights_(lights), distribution_(lights.empty() ? std::vector<float>{0.0f} : selection_weights(lights, selection)) {}

std::optional<LightSampler::Choice> LightSampler::sample(float u) const {
    if (lights_.empty()) return std::nullopt;
    const std::size_t i = distribution_.sample_discrete(u);
    return Choice{lights_[i].get(), distribution_.discrete_probability(i)};
}

float LightSampler::probability(const Light& light) const {
    if (lights_.empty()) return 0.0f;
    return distribution_.discrete_probability(light.index);
}

}  // namespace freezeray::ch03
