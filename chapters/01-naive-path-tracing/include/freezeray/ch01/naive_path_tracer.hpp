// Chapter 01: naive path tracing. The rendering equation estimated by following one random
// path per sample, choosing every bounce direction uniformly over the hemisphere and counting
// light only when the path happens to hit an emitter or leaves into the environment. Point, spot
// and directional lights (chapter 03) cannot be hit, so this integrator renders them black.
#pragma once

#include "freezeray/integrator.hpp"
#include "freezeray/scene.hpp"

namespace freezeray::ch01 {

// The default maximum path length, in segments (camera ray = 1). Chosen so that the Cornell
// box's mean radiance is within 1% of its infinite-depth value (measured in the book, chapter
// 01, "How deep is deep enough?").
inline constexpr int DefaultMaxDepth = 10;

class NaivePathTracer final : public PixelIntegrator {
public:
    explicit NaivePathTracer(int max_depth) : max_depth_(max_depth > 0 ? max_depth : DefaultMaxDepth) {}

    Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, ScratchArena& arena) const override;

    int max_depth() const { return max_depth_; }

private:
    int max_depth_;
};

}  // namespace freezeray::ch01
