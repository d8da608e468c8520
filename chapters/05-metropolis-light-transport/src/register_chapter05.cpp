// Chapter 05's registrations: the two Metropolis integrators and their options.
#include "freezeray/ch05/register_chapter05.hpp"
#include "freezeray/ch04/register_chapter04.hpp"

#include "freezeray/ch05/metropolis_light_transport.hpp"
#include "freezeray/ch05/auto_integrator.hpp"
#include "freezeray/ch05/sds_probe.hpp"

namespace freezeray {

namespace {

// Markov chains over bidirectional samples: their own streams, a splatting film (no resume), and
// they explore the paths they find.
constexpr IntegratorTraits ChainTraits{.samples_lights = true, .resumable = false, .explores_found_paths = true};

}  // namespace

void register_chapter05(Registry& registry) {
    register_chapter04(registry);  // chapters 01 to 04 first
    const ch05::MltSettings defaults;
    const std::vector<std::string> mlt_integrators = {"mlt", "mlt-multiplexed"};
    auto declare = [&](const char* flag, const char* key, OptionType type, const std::string& help) {
        registry.add_option({flag, key, type, OptionTarget::Integrator, help, mlt_integrators, 5});
    };
    declare("--mlt-large-step", "mlt_large_step", OptionType::Number,
            "mlt: the probability of a large step (default " + option_default_text(defaults.large_step_probability) + ")");
    declare("--mlt-sigma", "mlt_sigma", OptionType::Number,
            "mlt: the standard deviation of a small step in primary sample space (default " + option_default_text(defaults.sigma) + ")");
    declare("--mlt-bootstrap", "mlt_bootstrap", OptionType::Integer,
            "mlt: the number of bootstrap paths (default " + std::to_string(defaults.bootstrap_samples) + ")");
    declare("--mlt-chains", "mlt_chains", OptionType::Integer,
            "mlt: the number of Markov chains (default " + std::to_string(defaults.chains) + ")");

    registry.integrators.add("mlt", 5,
                            "Metropolis light transport in primary sample space, driving bdpt: Markov chains that "
                            "spend their samples where the light is",
                            {ChainTraits, [](const RenderSettings& settings, const Parameters& options) {
                                 return std::make_unique<ch05::MetropolisLightTransport>(
                                     ch05::read_mlt_settings(options, settings.max_depth, false));
                             }});
    registry.integrators.add("mlt-multiplexed", 5,
                            "multiplexed Metropolis light transport: each state one path length and one bdpt strategy, "
                            "chosen by the chain",
                            {ChainTraits, [](const RenderSettings& settings, const Parameters& options) {
                                 return std::make_unique<ch05::MetropolisLightTransport>(
                                     ch05::read_mlt_settings(options, settings.max_depth, true));
                             }});
    // With every candidate registered, the one chosen by measurement (chapters/05-metropolis-light-transport/src/auto_integrator.cpp).
    ch05::register_auto_integrator(registry, 5);
    // Where specular-diffuse-specular paths light much of the image, the chain (auto trusts only
    // the chains there too).
    registry.add_advice({"mlt", ch05::advise_chain, true});  // its probe traces paths
}

}  // namespace freezeray
