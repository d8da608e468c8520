// Chapter 04's registrations.
#include "freezeray/ch04/register_chapter04.hpp"

#include "freezeray/ch04/light_tracer.hpp"

namespace freezeray {

void register_chapter04(Registry& registry) {
    registry.add_integrator("light-tracing", 4,
                            "light tracing: paths from the lights, every vertex connected to the camera and splatted "
                            "(bdpt's t = 1 strategies alone)",
                            [](const RenderSettings& settings) {
                                ch04::LightTracingSettings s;
                                s.max_depth = settings.max_depth;
                                return std::make_unique<ch04::LightTracer>(s);
                            });
}

}  // namespace freezeray
