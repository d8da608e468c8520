// What chapter 05 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 05's integrator ("mlt"). Call after register_chapter04.
void register_chapter05(Registry& registry);

}  // namespace freezeray
