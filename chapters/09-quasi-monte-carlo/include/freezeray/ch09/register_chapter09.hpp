// What chapter 09 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 09's samplers ("stratified", "sobol") and makes sobol the default sampler.
// Call after the registrations of the chapters before it.
void register_chapter09(Registry& registry);

}  // namespace freezeray
