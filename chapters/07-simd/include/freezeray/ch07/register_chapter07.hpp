// What chapter 07 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 07's accelerator ("kdtree-simd", the default from this chapter on) and its
// --simd-width.
// Chapters 01 to 06 are registered first.
void register_chapter07(Registry& registry);

}  // namespace freezeray
