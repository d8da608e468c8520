// Chapter 10's registrations.
#include "freezeray/ch10/register_chapter10.hpp"
#include "freezeray/ch09/register_chapter09.hpp"

#include "freezeray/ch10/bvh_light_sampler.hpp"
#include "freezeray/ch10/defensive_light_sampler.hpp"

namespace freezeray {

void register_chapter10(Registry& registry) {
    register_chapter09(registry);  // chapters 01 to 09 first
    registry.light_samplers.add("bvh", 10,
                               "a light BVH walked from the shading point, each light in proportion to a bound on what it "
                               "can send there (Conty Estevez and Kulla 2018), with a defensive share of 0.2 of the choices "
                               "uniform; environment and directional lights beside the tree",
                               [](const std::vector<std::unique_ptr<Light>>& lights, const Parameters&) {
                                   return std::make_unique<ch10::DefensiveLightSampler>(
                                       std::make_unique<ch10::BvhLightSampler>(lights), lights, ch10::DefensiveShare);
                               });
    registry.light_samplers.add("bvh-tree", 10,
                               "the light BVH alone, without bvh's defensive share (for comparison)",
                               [](const std::vector<std::unique_ptr<Light>>& lights, const Parameters&) {
                                   return std::make_unique<ch10::BvhLightSampler>(lights);
                               });
    registry.light_samplers.set_default("bvh");
}

}  // namespace freezeray
