// What chapter 10 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 10's light sampler ("bvh") and makes it the default light sampler. Call after
// the registrations of the chapters before it.
void register_chapter10(Registry& registry);

}  // namespace freezeray
