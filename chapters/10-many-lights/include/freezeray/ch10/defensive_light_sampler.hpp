// A defensive mixture: another light sampler's choice, with a fixed share of the choices made
// uniformly instead (book chapter 10, "A defensive share"; Hesterberg, "Weighted average
// importance sampling and defensive mixture distributions", Technometrics 37(2), 1995; Owen and
// Zhou, "Safe and effective importance sampling", JASA 95(449), 2000).
//
// The light BVH chooses by a bound on what each light can send to the point, which knows nothing
// of the surface's BSDF: where a glossy surface reflects a weak light and not a strong one, the
// tree gives the light that matters few samples. Mixed with uniform choice, every light keeps at
// least share / N of the samples, and the density is
//     p(light) = (1 - share) p_tree(light) + share / N,
// so where the tree is right its variance grows by at most 1 / (1 - share) (each light's density
// is at least (1 - share) of the tree's), and where it is wrong the uniform part bounds the loss.
#pragma once

#include "freezeray/ch03/fixed_light_sampler.hpp"
#include "freezeray/light_sampler.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace freezeray::ch10 {

// The share of `bvh`'s choices made uniformly (book chapter 10 measures 0.1 to 0.3).
inline constexpr float DefensiveShare = 0.2f;

class DefensiveLightSampler final : public LightSampler {
public:
    // `primary` chooses among `lights` (which must outlive this); `share` in [0, 1).
    DefensiveLightSampler(std::unique_ptr<LightSampler> primary, const std::vector<std::unique_ptr<Light>>& lights,
                          float share);

    // u below the share, rescaled, chooses uniformly; above it, rescaled, `primary` chooses. Either
    // way the probability reported is the mixture's, as probability() gives it to the bit.
    std::optional<LightChoice> sample(const ShadingPoint& point, float u) const override;
    float probability(const ShadingPoint& point, const Light& light) const override;
    std::vector<std::string> description() const override;

private:
    // (1 - share) p_primary + share p_uniform, computed in one order wherever it is needed.
    float mixture(float primary_probability, float uniform_probability) const {
        return (1.0f - share_) * primary_probability + share_ * uniform_probability;
    }

    std::unique_ptr<LightSampler> primary_;
    ch03::FixedLightSampler uniform_;
    float share_;
};

}  // namespace freezeray::ch10
