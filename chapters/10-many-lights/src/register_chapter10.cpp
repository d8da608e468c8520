// Chapter 10's registrations.
#include "freezeray/ch10/register_chapter10.hpp"

#include "freezeray/ch10/bvh_light_sampler.hpp"

namespace freezeray {

void register_chapter10(Registry& registry) {
    registry.add_light_sampler("bvh", 10,
                               "a light BVH walked from the shading point: each light in proportion to a bound on what it "
                               "can send there (Conty Estevez and Kulla 2018); environment and directional lights beside it",
                               [](const std::vector<std::unique_ptr<Light>>& lights, const Parameters&) {
                                   return std::make_unique<ch10::BvhLightSampler>(lights);
                               });
    registry.set_default_light_sampler("bvh");
}

}  // namespace freezeray
