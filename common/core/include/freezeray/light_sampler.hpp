// Light samplers: which light a path samples at a shading point (next-event estimation). The
// interface lives here so that the registry can name them and a render can carry one; chapter 03
// chooses by power or uniformly, the same everywhere, and chapter 10 by a light BVH that looks at
// the shading point (Conty Estevez and Kulla, "Importance Sampling of Many Lights with Adaptive
// Tree Splitting", 2018).
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/hit.hpp"
#include "freezeray/light.hpp"
#include "freezeray/math.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace freezeray {

// Where light is wanted: a point and, on a surface, its shading normal (zero when there is no
// surface, as for a point in space). The normal's sign does not matter: a surface may receive
// light from either side (transmission), so a sampler may only use |cos|.
struct ShadingPoint {
    Vec3 position{0.0f};
    Vec3 normal{0.0f};
    // Where the BSDF there sends most of its light, when it is one glossy lobe (a rough metal):
    // the lobe's axis (the mirror direction of wo, unit length) and its microfacet roughness
    // alpha; alpha 0 when the BSDF has no such lobe. A sampler may use it to prefer the lights
    // the lobe looks at (chapter 10, "The lobe at the point"), never to leave a light out.
    Vec3 lobe_axis{0.0f};
    float lobe_alpha = 0.0f;
};

// The light sampler's view of a surface vertex: its position, shading normal and, when the BSDF
// seen from wo (shading frame) is one glossy lobe, that lobe's axis in world space and its
// roughness. A path tracer keeps it for the MIS weight of the emission its BSDF sample finds, so
// that probability() is asked about the same point as sample() was.
inline ShadingPoint shading_point(const Hit& hit, const Frame& frame, const Vec3& wo, const BSDF& bsdf) {
    ShadingPoint point{hit.position, hit.shading_normal};
    if (const std::optional<GlossyLobe> lobe = bsdf.glossy_lobe(wo)) {
        point.lobe_axis = glm::normalize(frame.to_world(lobe->axis));
        point.lobe_alpha = lobe->alpha;
    }
    return point;
}

// A light chosen for a shading point, and the probability that it was this one.
struct LightChoice {
    const Light* light = nullptr;
    float probability = 0.0f;
};

class LightSampler {
public:
    virtual ~LightSampler() = default;

    // One light chosen with u in [0, 1) for `point`; nothing when no light can send light there
    // (or the scene has none).
    virtual std::optional<LightChoice> sample(const ShadingPoint& point, float u) const = 0;

    // The probability that sample() chooses `light` for `point`, exactly as sample() reports it
    // (MIS weights of emission found by BSDF sampling need it). 0 means sample() never chooses
    // it there, which a sampler may say only where the light sends no light to the point.
    virtual float probability(const ShadingPoint& point, const Light& light) const = 0;

    // Lines for `info` and `render` (a tree's size and build time); may be empty.
    virtual std::vector<std::string> description() const { return {}; }
};

// Makes a light sampler over a scene's lights (which must outlive it), with its settings.
class Parameters;
using LightSamplerFactory =
    std::function<std::unique_ptr<LightSampler>(const std::vector<std::unique_ptr<Light>>& lights, const Parameters& options)>;

}  // namespace freezeray
