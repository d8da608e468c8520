// What chapter 04 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 04's integrators ("light-tracing", "bdpt", "bdpt-balance").
// Chapters 01 to 03 are registered first.
void register_chapter04(Registry& registry);

}  // namespace freezeray
