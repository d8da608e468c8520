// What chapter 07 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 07's accelerator ("kdtree-simd", the default from this chapter on) and its
// --simd-width. Call after register_chapter06.
void register_chapter07(Registry& registry);

}  // namespace freezeray
