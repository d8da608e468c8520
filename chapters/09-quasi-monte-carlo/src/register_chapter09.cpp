// Chapter 09's registrations: the stratified and Sobol samplers, and Sobol as the default
// sampler of the per-pixel integrators from this chapter on.
#include "freezeray/ch09/register_chapter09.hpp"
#include "freezeray/ch08/register_chapter08.hpp"

#include "freezeray/ch09/sobol_sampler.hpp"
#include "freezeray/ch09/stratified_sampler.hpp"
#include "freezeray/ch09/zsobol_sampler.hpp"

namespace freezeray {

void register_chapter09(Registry& registry) {
    register_chapter08(registry);  // chapters 01 to 08 first
    registry.samplers.add("stratified", 9,
                         "jittered: every 1D and 2D draw stratified over each block of 1, 1, 2, 4, 8, ... samples of a pixel",
                         [](const Parameters&) { return std::make_unique<ch09::StratifiedSampler>(); });
    registry.samplers.add("sobol", 9,
                         "Sobol (0,2)-sequence per dimension pair, index shuffled and points Owen-scrambled by hashing "
                         "(Burley 2020), independent across pairs and pixels",
                         [](const Parameters&) { return std::make_unique<ch09::SobolSampler>(); });
    registry.samplers.add("zsobol", 9,
                         "Sobol over Morton-ordered pixels (Ahmed and Wonka 2020, pbrt-v4's ZSobol): neighbouring pixels take "
                         "complementary blocks of one sequence, so the error is blue noise when --spp is known",
                         [](const Parameters&) { return std::make_unique<ch09::ZSobolSampler>(); });
    registry.samplers.set_default("sobol");
}

}  // namespace freezeray
