// Chapter 05's registrations.
#include "freezeray/ch05/register_chapter05.hpp"

#include "freezeray/ch05/metropolis_light_transport.hpp"

namespace freezeray {

void register_chapter05(Registry& registry) {
    registry.add_integrator("mlt", 5,
                            "Metropolis light transport in primary sample space, driving bdpt: Markov chains that "
                            "spend their samples where the light is",
                            [](const RenderSettings& settings) {
                                ch05::MltSettings s;
                                s.max_depth = settings.max_depth;
                                return std::make_unique<ch05::MetropolisLightTransport>(s);
                            });
    registry.add_integrator("mlt-multiplexed", 5,
                            "multiplexed Metropolis light transport: each state one path length and one bdpt strategy, "
                            "chosen by the chain",
                            [](const RenderSettings& settings) {
                                ch05::MltSettings s;
                                s.max_depth = settings.max_depth;
                                s.multiplexed = true;
                                return std::make_unique<ch05::MetropolisLightTransport>(s);
                            });
}

}  // namespace freezeray
