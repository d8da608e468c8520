// Chapter 03's path tracers: at every non-specular vertex one light is sampled directly
// (next-event estimation), and the emission that BSDF sampling finds is either skipped where
// light sampling already counted it (`pt-nee`) or weighted against it by multiple importance
// sampling (`pt-mis`; Veach and Guibas 1995).
#pragma once

#include "freezeray/integrator.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/ch03/fixed_light_sampler.hpp"
#include "freezeray/ch03/mis.hpp"

namespace freezeray::ch03 {

// How light sampling and BSDF sampling are combined.
enum class Combination {
    NextEventEstimation,        // light samples only; BSDF samples count emission only after a specular bounce
    MultipleImportanceSampling, // both, weighted by a heuristic
};

struct LightSamplingSettings {
    Combination combination = Combination::MultipleImportanceSampling;
    MisHeuristic heuristic = MisHeuristic::Power;
    // The light sampler when the render names none (RenderSettings::light_sampler); the
    // `-uniform` variants fix it.
    LightSelection selection = LightSelection::Power;
    bool selection_fixed = false;
    int max_depth = 0;  // segments; 0: chapter 02's default
};

class LightSamplingPathTracer final : public Integrator {
public:
    explicit LightSamplingPathTracer(const LightSamplingSettings& settings);

    RenderResult render(const Scene& scene, const RenderSettings& settings, Progress& progress) const override;

    // One sample of the radiance arriving along `ray`.
    Spectrum li(const Ray& ray, const Scene& scene, const LightSampler& lights, Sampler& sampler, ScratchArena& arena) const;

private:
    LightSamplingSettings settings_;
};

}  // namespace freezeray::ch03
