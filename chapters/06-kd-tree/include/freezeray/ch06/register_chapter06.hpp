// What chapter 06 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 06's accelerator ("kdtree").
// Chapters 01 to 05 are registered first.
void register_chapter06(Registry& registry);

}  // namespace freezeray
