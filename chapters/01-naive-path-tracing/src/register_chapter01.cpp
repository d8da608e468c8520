// Chapter 01's registrations.
#include "freezeray/ch01/register_chapter01.hpp"

#include "freezeray/ch01/naive_path_tracer.hpp"

namespace freezeray {

void register_chapter01(Registry& registry) {
    registry.add_integrator("pt-naive", 1, "naive path tracing: uniform hemisphere sampling, emission found by hitting it",
                            [](const RenderSettings& settings) {
                                return std::make_unique<ch01::NaivePathTracer>(settings.max_depth);
                            });
}

}  // namespace freezeray
