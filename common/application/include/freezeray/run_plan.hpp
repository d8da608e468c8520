// The plan of a run: everything a render is made of, assembled once and complete before
// Integrator::render is called. `render`, every run of `compare` and `compare --make-reference`
// are planned here, and chapter 05's `auto` hands the plan's settings to its pilots; so a choice
// (which sampler, which light sampler, which options, which budget) is made by one rule, with one
// message when it is wrong.
#pragma once

#include "freezeray/capability_choice.hpp"
#include "freezeray/integrator.hpp"
#include "freezeray/options.hpp"
#include "freezeray/registry.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace freezeray {

class Scene;

// A run as `compare --integrators` names it: an integrator, then after each @ the name of a
// capability of a kind chosen per run (a sampler, a light sampler: KindDescription::per_run), at
// most one of each kind: pt-mis, pt-mis@sobol, pt-mis@bvh, pt-mis@sobol@bvh.
struct RunName {
    std::string integrator;
    Selections named;  // by kind
};
// An unknown name after an @ is an InputError at `where`.
RunName parse_run_name(const std::string& run, const Registry& registry, const std::string& where = "--integrators");

// What a command asks of one run, as typed: what is not given comes from the scene, else from
// the renderer's defaults.
struct RunRequest {
    std::string run;                        // a RunName; an empty integrator: the scene's, else the suggested one
    std::string where = "--integrator";     // where `run` was given, for messages
    Selections selections;                  // the command line's selectors; the run's own @ names go over them
    OptionValues options;                   // the chapters' options given on the command line
    std::uint64_t samples_per_pixel = 0;    // 0: the scene's (no limit when a time or an error target decides)
    double time_seconds = 0.0;              // > 0: render for this long
    double target_error = 0.0;              // > 0: stop at this estimated relMSE
    int threads = 0;                        // 0: every core
    std::optional<std::uint64_t> seed;      // unset: the scene's
    std::uint64_t first_sample = 0;
    int max_depth = -1;                     // negative: the scene's
};

// A run ready to render.
struct RunPlan {
    std::string name;                        // as requested: "pt-mis@sobol" (the integrator's name when no @)
    std::string integrator_name;
    IntegratorTraits traits;
    RenderSettings settings;                 // budget, seed, depth, sampler and light sampler
    std::string sampler_name;                // the sampler the settings hold ("independent" when none)
    std::string light_sampler_name;          // empty: the integrator's own choice
    std::unique_ptr<OptionParameters> options;  // the integrator's options: the scene's "render" block under the flags
    std::unique_ptr<Integrator> integrator;  // made from settings and options
    std::vector<std::string> warnings;       // about the run (a light no path can reach)
};

// Plans each request over one loaded scene. The chapters' options given on the command line must
// be read by at least one of the runs' integrators (else an InputError at the flag); each run's
// integrator reads those it knows. Every name is checked before anything renders.
std::vector<RunPlan> plan_runs(const std::vector<RunRequest>& requests, const Scene& scene, const Registry& registry);
RunPlan plan_run(const RunRequest& request, const Scene& scene, const Registry& registry);

// The light sampler a render at this scene uses when neither the command line nor the run names
// one: the scene's, else the renderer's default (empty before chapter 03). `info` shows it.
CapabilityChoice scene_light_sampler(const Scene& scene, const Registry& registry);

}  // namespace freezeray
