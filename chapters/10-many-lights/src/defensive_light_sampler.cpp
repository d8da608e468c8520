// The defensive mixture of a light sampler and uniform choice (see defensive_light_sampler.hpp).
#include "freezeray/ch10/defensive_light_sampler.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace freezeray::ch10 {

DefensiveLightSampler::DefensiveLightSampler(std::unique_ptr<LightSampler> primary,
                                             const std::vector<std::unique_ptr<Light>>& lights, float share)
    : primary_(std::move(primary)), uniform_(lights, ch03::LightSelection::Uniform), share_(share) {
    if (!(share >= 0.0f && share < 1.0f)) throw std::invalid_argument("defensive light sampler: the share must be in [0, 1)");
}

// BOOK(defensive-sample)
std::optional<LightChoice> DefensiveLightSampler::sample(const ShadingPoint& point, float u) const {
    if (u < share_) {
        // Uniformly; the probability must still be the mixture's, which needs the tree's too.
        const std::optional<LightChoice> choice = uniform_.sample(std::min(u / share_, OneMinusEpsilon));
        if (!choice) return std::nullopt;
        return LightChoice{choice->light, probability(point, *choice->light)};
    }
    const std::optional<LightChoice> choice = primary_->sample(point, std::min((u - share_) / (1.0f - share_), OneMinusEpsilon));
    if (!choice) return std::nullopt;  // no light the primary sampler could choose sends light here
    return LightChoice{choice->light, mixture(choice->probability, uniform_.probability(*choice->light))};
}

float DefensiveLightSampler::probability(const ShadingPoint& point, const Light& light) const {
    return mixture(primary_->probability(point, light), uniform_.probability(light));
}
// END BOOK

std::vector<std::string> DefensiveLightSampler::description() const {
    std::vector<std::string> lines = primary_->description();
    char line[128];
    std::snprintf(line, sizeof line, "defensive share: %.2g of the choices uniform over all lights", static_cast<double>(share_));
    lines.emplace_back(line);
    return lines;
}

}  // namespace freezeray::ch10
