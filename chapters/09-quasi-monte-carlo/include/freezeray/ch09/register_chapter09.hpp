// What chapter 09 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 09's samplers ("stratified", "sobol") and makes sobol the default sampler.
// Chapters 01 to 08 are registered first.
void register_chapter09(Registry& registry);

}  // namespace freezeray
