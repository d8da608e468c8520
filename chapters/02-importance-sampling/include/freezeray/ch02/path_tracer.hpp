// Chapter 02: path tracing with BSDF importance sampling and Russian roulette (`pt-is`). Like
// chapter 01 it finds light only by hitting it: emitters and the environment, never point, spot or
// directional lights, which it renders black (chapter 03 samples them).
#pragma once

#include "freezeray/integrator.hpp"
#include "freezeray/scene.hpp"

namespace freezeray::ch02 {

// Paths are ended by Russian roulette, which keeps the estimator unbiased; the maximum depth is
// only a guard against paths trapped between mirrors.
inline constexpr int DefaultMaxDepth = 64;
// Russian roulette starts after this many segments (the first bounces carry most of the light).
inline constexpr int RussianRouletteStart = 3;

class ImportanceSampledPathTracer final : public PixelIntegrator {
public:
    explicit ImportanceSampledPathTracer(int max_depth) : max_depth_(max_depth > 0 ? max_depth : DefaultMaxDepth) {}

    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, ScratchArena& arena) const override;

private:
    int max_depth_;
};

// Russian roulette (Arvo and Kirk, "Particle Transport and Image Synthesis", 1990; pbrt-v3,
// section 14.5.1), for a path whose weight so far is `weight`. The path continues with
// probability q, the largest component of its weight but at most 0.95 (paths that carry little
// light stop more often, and even bright ones end), decided by u in [0, 1): it continues when
// u < q. A survivor's weight is divided by q, so that the expected value is unchanged. Returns
// the q a survivor was divided by (for whatever else the caller divides by it, as BDPT's subpaths
// do), or 0 when the path ends, its weight then left as it was.
float russian_roulette(Spectrum& weight, float u);

}  // namespace freezeray::ch02
