// What chapter 06 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 06's accelerator ("kdtree"). Call after register_chapter05.
void register_chapter06(Registry& registry);

}  // namespace freezeray
