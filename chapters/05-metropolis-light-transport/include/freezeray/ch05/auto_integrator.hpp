// `auto`: the integrator chosen for a scene by measurement, not by guess. A short pilot render
// with each candidate estimates its efficiency 1 / (relMSE x seconds) from its own per-pixel
// variance; a candidate whose estimate cannot be trusted is left out (one that rises as samples
// are added, or one whose image disagrees beyond their noise with the others' while they agree:
// light it has not found yet); the most efficient of the others renders the rest, keeping its
// pilot. Before the pilots, a probe with rays measures how much of the image rests on
// specular-diffuse-specular paths (sds_probe.hpp); where that is much, only the candidates that
// explore the paths they find (the Metropolis chains) are piloted, and a single candidate left
// renders the whole budget without one.
#pragma once

#include "freezeray/integrator.hpp"
#include "freezeray/registry.hpp"

#include <memory>
#include <string>
#include <vector>

namespace freezeray::ch05 {

// What the pilot of one candidate measured.
struct PilotMeasurement {
    std::string integrator;
    double seconds = 0.0;
    std::uint64_t samples_per_pixel = 0;
    double estimated_relative_mse = -1.0;
    double efficiency = 0.0;        // 1 / (estimated relMSE x seconds); 0 when there is no estimate
    std::string disqualified;       // why the estimate cannot be trusted; empty when it can
};

// Which candidate the pilots choose: the most efficient qualified one, else (when none
// qualifies) the most efficient of all, said to be a guess. `pilots` must not be empty.
struct IntegratorChoice {
    std::size_t chosen = 0;   // index into the pilots
    std::string reason;       // one line: what was chosen, and why
};
IntegratorChoice choose_by_pilots(const std::vector<PilotMeasurement>& pilots);

class AutoIntegrator final : public Integrator {
public:
    static constexpr std::uint64_t PilotSamples = 4;      // per pixel: estimates at 2 and 4 to compare
    static constexpr double RisingTolerance = 1.0;        // the estimate at 4 spp must fall below this x that at 2

    struct Candidate {
        std::string name;
        IntegratorTraits traits;
        std::unique_ptr<Integrator> integrator;
    };
    explicit AutoIntegrator(std::vector<Candidate> candidates) : candidates_(std::move(candidates)) {}

    RenderResult render(const Scene& scene, const RenderSettings& settings, Progress& progress) const override;

private:
    std::vector<Candidate> candidates_;
};

// Registers `auto` for `chapter` with the candidates the registry has among pt-mis, bdpt and
// mlt (in that order; mlt-multiplexed is left out: its error estimate cannot see the error of its
// normalisation, which dominates it in the book's measurements).
void register_auto_integrator(Registry& registry, int chapter);

}  // namespace freezeray::ch05
