// Metropolis light transport in primary sample space (`mlt`; Kelemen, Szirmay-Kalos, Antal and
// Csonka 2002; Veach and Guibas 1997 for MLT itself; pbrt-v3, section 16.4): Markov chains whose
// states are the uniform numbers of a chapter 04 bidirectional sample, so that samples gather
// where the image carries light.
#pragma once

#include "freezeray/integrator.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/ch04/bidirectional_path_tracer.hpp"
#include "freezeray/ch05/primary_samples.hpp"

#include <cstdint>
#include <vector>

namespace freezeray::ch05 {

struct MltSettings {
    int max_depth = 0;                    // segments of a whole path; 0: chapter 02's default
    float large_step_probability = 0.3f;  // p_large (Kelemen et al. 2002 use 0.3 as well)
    float sigma = 0.01f;                  // the small steps' standard deviation (pbrt-v3's default)
    std::uint64_t bootstrap_samples = 100000;
    int chains = 1000;
    // Multiplexed MLT (Hachisuka, Kaplanyan and Dachsbacher 2014): a state is one path length
    // and one strategy (s, t), chosen by the chain, instead of a whole bidirectional sample.
    bool multiplexed = false;
};

// The settings above from an mlt integrator's parameters (the scene's "render" block and the
// options register_chapter05 declares: mlt_large_step, mlt_sigma, mlt_bootstrap, mlt_chains),
// each checked; keys left out keep the defaults written above.
MltSettings read_mlt_settings(const Parameters& options, int max_depth, bool multiplexed);

// One bidirectional sample's contributions and its scalar value, the target function of the
// chain: I(u) = the sum of the luminances of the sample's MIS-weighted contributions.
struct PathContributions {
    struct Splat {
        Vec2 raster_position;
        Spectrum value;
    };
    std::vector<Splat> splats;
    float value = 0.0f;
    std::uint64_t invalid = 0;  // NaN, Inf or negative contributions left out (a bug if any)
};

// Starts evaluating a state: clears `out` and the arena, starts the camera stream and returns the
// film position its first two numbers give (anywhere on the film: chains roam the whole image).
Vec2 start_path(const Scene& scene, PrimarySamples& samples, ScratchArena& arena, PathContributions& out);

// Evaluates the bidirectional sample that `samples` describes: the film position from the first
// two numbers of the camera stream (anywhere on the film), then chapter 04's bidirectional_sample.
void evaluate_path(const Scene& scene, const ch03::FixedLightSampler& lights, const ch04::BidirectionalSettings& settings,
                   PrimarySamples& samples, ScratchArena& arena, ch04::SubpathStorage& storage, PathContributions& out);

// Multiplexed MLT's state (Hachisuka et al. 2014; pbrt-v3, section 16.4): a path of `segments`
// segments made by one strategy (s, t), s chosen by the camera stream's third number; its
// contribution is that strategy's MIS-weighted estimate divided by the probability 1 / (segments
// + 1) of choosing it. Nothing when the subpaths do not reach the lengths the strategy needs.
void evaluate_multiplexed_path(const Scene& scene, const ch03::FixedLightSampler& lights,
                               const ch04::BidirectionalSettings& settings, int segments, PrimarySamples& samples,
                               ScratchArena& arena, ch04::SubpathStorage& storage, PathContributions& out);

// The path length of bootstrap sample i in multiplexed MLT: every length 1 ... max_depth in turn.
inline int multiplexed_segments(std::uint64_t index, int max_depth) {
    return 1 + static_cast<int>(index % static_cast<std::uint64_t>(max_depth));
}

// The bootstrap (Veach 1997, section 11.3.1; pbrt-v3, section 16.4): independent samples whose
// values estimate the normalisation b = the integral of I over primary sample space (the mean
// image luminance) and from which the chains' starting states are drawn in proportion to I.
struct Bootstrap {
    std::vector<float> values;  // I of bootstrap sample i
    double b = 0.0;             // their mean
    double standard_error = 0.0;
};
Bootstrap run_bootstrap(const Scene& scene, const ch03::FixedLightSampler& lights, const ch04::BidirectionalSettings& bidirectional,
                        const MltSettings& settings, std::uint64_t seed, int threads);  // threads 0: every core

// The generator of bootstrap sample i (and of the chain that starts from it, until it mutates).
PCG32 bootstrap_stream(std::uint64_t seed, std::uint64_t index);

class MetropolisLightTransport final : public Integrator {
public:
    explicit MetropolisLightTransport(const MltSettings& settings);

    RenderResult render(const Scene& scene, const RenderSettings& settings, Progress& progress) const override;

private:
    MltSettings settings_;
};

}  // namespace freezeray::ch05
