// Bidirectional path tracing (`bdpt`): a camera subpath and a light subpath per sample, joined
// in every possible way (s light vertices, t camera vertices), each way weighted by multiple
// importance sampling against all the others (Veach and Guibas 1995; Veach 1997, chapter 10;
// pbrt-v3, section 16.3).
#pragma once

#include "freezeray/integrator.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/ch04/camera_importance.hpp"
#include "freezeray/ch04/light_path_loop.hpp"
#include "freezeray/ch04/sample_stream.hpp"
#include "freezeray/ch03/mis.hpp"
#include "freezeray/ch04/path_vertex.hpp"

#include <functional>
#include <string>
#include <vector>

namespace freezeray::ch04 {

// What strategy (s, t) contributes for one pair of subpaths.
struct StrategyContribution {
    Spectrum unweighted{0.0f};  // the strategy's own estimate of the path's contribution
    float weight = 0.0f;        // its MIS weight
    bool at_raster = false;     // t = 1: lands at raster_position, not at the camera ray's pixel
    Vec2 raster_position{0.0f};
};

// Joins the first s vertices of the light subpath and the first t of the camera subpath
// (Veach 1997, section 10.2): s = 0 uses emission found by the camera subpath, s = 1 samples a
// point on a light, t = 1 connects to the camera (through its importance), others connect the
// two end vertices deterministically. Uses random numbers only for s = 1.
StrategyContribution connect_strategy(const Scene& scene, const ch03::FixedLightSampler& lights, ch03::MisHeuristic heuristic,
                                      const PathVertex* light, int s, const PathVertex* camera, int t,
                                      SampleStream& samples);

struct BidirectionalSettings {
    int max_depth = 0;  // segments of a whole path; 0: chapter 02's default
    ch03::MisHeuristic heuristic = ch03::MisHeuristic::Power;
    // Where to write each strategy's image (`--bdpt-strategies`, strategy_images.hpp); empty:
    // none are made.
    std::string strategy_images_folder;
};

// The settings above from a bdpt integrator's parameters (the scene's "render" block and the
// option register_chapter04 declares: bdpt_strategies, a folder, checked to take files).
BidirectionalSettings read_bidirectional_settings(const Parameters& options, int max_depth,
                                                  ch03::MisHeuristic heuristic);

// One contribution of a bidirectional sample: where it lands on the film and how much.
struct BidirectionalContribution {
    Vec2 raster_position;
    Spectrum weighted;    // MIS-weighted: what the image adds
    Spectrum unweighted;  // the strategy alone
    int s = 0, t = 0;
};

// The subpaths' storage, reused from sample to sample (no allocation per sample).
struct SubpathStorage {
    std::vector<PathVertex> camera, light;
};

// One bidirectional sample (Veach 1997, section 10.2): a camera subpath through film position
// `film` (pixels) and a light subpath, joined in every strategy (s, t) of at most max_depth
// segments; `record` receives each non-zero contribution. The caller has started CameraStream
// (and drawn the film position from it); the light subpath and the connections use their own
// streams. Chapter 05's Metropolis light transport drives this same function.
void bidirectional_sample(const Scene& scene, const ch03::FixedLightSampler& lights, const BidirectionalSettings& settings,
                          const Vec2& film, SampleStream& samples, ScratchArena& arena, SubpathStorage& storage,
                          const std::function<void(const BidirectionalContribution&)>& record);

class BidirectionalPathTracer final : public Integrator {
public:
    explicit BidirectionalPathTracer(const BidirectionalSettings& settings);

    RenderResult render(const Scene& scene, const RenderSettings& settings, Progress& progress) const override;

private:
    BidirectionalSettings settings_;
};

}  // namespace freezeray::ch04
