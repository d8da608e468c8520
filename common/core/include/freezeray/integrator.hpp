// Integrators: from a scene to an image with an estimate of its error.
#pragma once

#include "freezeray/film.hpp"
#include "freezeray/image.hpp"
#include "freezeray/light_sampler.hpp"
#include "freezeray/ray.hpp"
#include "freezeray/sampler.hpp"
#include "freezeray/scratch_arena.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace freezeray {

class Scene;
class Progress;

// How long to render and with what: what every integrator shares. Plain data with defaults;
// parsed in one place (cli.cpp, with defaults from the scene's "render" block). An integrator's
// own settings come to its factory as Parameters (registry.hpp).
struct RenderSettings {
    std::uint64_t samples_per_pixel = 16;  // used when time_seconds and target_error are 0
    double time_seconds = 0.0;             // > 0: render until this much wall time has passed
    double target_error = 0.0;             // > 0: stop when the estimated relMSE falls below it
    int threads = 0;                       // 0: every core
    std::uint64_t seed = 0;
    int max_depth = 0;                     // 0: the integrator's default
    // Called after every pass with the film so far (for checkpoints and convergence plots);
    // the time it takes is not counted as render time.
    std::function<void(const Film& film, std::uint64_t samples_per_pixel, double seconds)> on_pass;
    // Set (by a signal handler) to stop after the current tile; the result holds what was done.
    const std::atomic<bool>* stop_requested = nullptr;
    // Sample indices start here, so that several machines can each render a different range of
    // one seed's samples and `merge` them (`--sample-offset`).
    std::uint64_t first_sample = 0;
    // A film to continue (`--resume`): every pixel goes on from its own sample count, so an
    // interrupted and resumed render equals the uninterrupted one bit for bit.
    std::shared_ptr<const Film> resume;
    // > 0: passes are shortened so that none takes much longer than this (checkpoints are
    // written between passes).
    double max_pass_seconds = 0.0;
    // Where the per-pixel integrators' numbers come from (chapter 09's `--sampler`); each thread
    // renders with its own clone. Null: the independent sampler.
    std::shared_ptr<const Sampler> sampler;
    // How lights are chosen at shading points (`--light-sampler`: chapter 03's power or uniform,
    // chapter 10's bvh), built over the scene's lights. Null: the integrator's own choice.
    std::shared_ptr<const LightSampler> light_sampler;
};

struct RenderResult {
    Image image;                     // the estimate (per-pixel mean)
    std::shared_ptr<const Film> film;  // the film itself (to resume, or to merge exactly); may be null
    Image variance;                  // per-pixel variance of the mean (empty if not estimable)
    std::uint64_t samples_per_pixel = 0;
    double seconds = 0.0;
    std::uint64_t invalid_samples = 0;    // NaN, Inf or negative samples (a bug when non-zero)
    double estimated_relative_mse = -1.0; // from `variance`; negative when not estimable
    bool interrupted = false;
    // Extra images the integrator made besides the estimate, by file name, and the folder they go
    // into (an integrator's own option chooses it, and checks it before rendering). `render`
    // makes the folder after the render and writes them there.
    std::vector<std::pair<std::string, Image>> extra_images;
    std::string extra_images_folder;
    // What the user should know about this render (printed by `render` as warnings and notes:
    // a scene whose light no path reaches, a Markov chain's acceptance rate).
    std::vector<std::string> warnings;
    std::vector<std::string> notes;
    // An integrator that hands the render to another (`auto`) names the one that made the image,
    // and why it was chosen; both empty otherwise.
    std::string integrator;
    std::string integrator_choice;
};

// What an integrator is, declared once when it is registered (Registry::integrators), so that a
// run is set up before any integrator is made: which sampler and light sampler it takes, which
// lights it can find, whether a saved render of it can go on.
struct IntegratorTraits {
    // It samples lights directly, and so finds point, spot and directional lights, which no ray
    // can hit (chapter 03).
    bool samples_lights = false;
    // It draws its numbers from RenderSettings::sampler (the per-pixel loop, render_pixels, and
    // bidirectional path tracing, whose samples belong to pixels); the others (light tracing,
    // Markov chains) use their own streams, and `--sampler` other than independent is refused
    // for them.
    bool draws_from_sampler = false;
    // It chooses a light at each shading point through RenderSettings::light_sampler (chapter 03's
    // light-sampling path tracers); the others refuse a named `--light-sampler`.
    bool chooses_lights_per_point = false;
    // A saved render can be continued exactly (`--resume`): its film's state is a per-pixel sample
    // count that a pass can go on from.
    bool resumable = true;
    // A Markov chain over paths (chapter 05): once it has found a rare bright path it explores the
    // paths near it, so its error does not hang on how seldom such a path is sampled from
    // scratch. `auto` trusts only these where much of the image rests on
    // specular-diffuse-specular paths (chapter 05's sds_probe.hpp), which the others sample from
    // scratch with one strategy only.
    bool explores_found_paths = false;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual RenderResult render(const Scene& scene, const RenderSettings& settings, Progress& progress) const = 0;
};

// One sample of the radiance arriving along a camera ray. All randomness from `sampler`, which
// has started the pixel sample; scratch allocations in `arena`, which is reset before every call.
using RadianceEstimator = std::function<Spectrum(const Ray& ray, Sampler& sampler, ScratchArena& arena)>;

// One clone of `prototype` per thread for a render of width x height pixels, each seeded with the
// render's seed and told the samples per pixel the render plans (0 when a time budget or a target
// error decides, see Sampler::plan_render). Both image loops use it: render_pixels, and chapter
// 04's render_light_paths for bidirectional samples.
std::vector<std::unique_ptr<Sampler>> thread_samplers(const Sampler& prototype, const RenderSettings& settings,
                                                      int threads, int width, int height);

// The image loop shared by every per-pixel integrator: passes of samples over all tiles until the
// sample count, the time budget or the target error is reached; each sample from its own stream.
RenderResult render_pixels(const Scene& scene, const RenderSettings& settings, Progress& progress,
                           const RadianceEstimator& li);

// An integrator that estimates each pixel independently from camera paths: it only says how one
// camera ray's radiance is estimated (li); the image loop, the film and the passes are shared.
// (An integrator that needs per-scene data, such as chapter 03's light sampler, derives from
// Integrator and calls render_pixels itself.)
class PixelIntegrator : public Integrator {
public:
    RenderResult render(const Scene& scene, const RenderSettings& settings, Progress& progress) const override;

    // One sample of the radiance arriving along `ray`. All randomness from `sampler`, by
    // dimension (sampler.hpp); scratch allocations in `arena`, which is reset before every call.
    virtual Spectrum li(const Ray& ray, const Scene& scene, Sampler& sampler, ScratchArena& arena) const = 0;
};

}  // namespace freezeray
