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

// The probability of continuing a path with this throughput (pbrt-v3, section 14.5.1): paths
// that carry little light are stopped more often, and survivors are reweighted by 1 / p.
float russian_roulette_continue_probability(const Spectrum& throughput);

}  // namespace freezeray::ch02
