// What chapter 08 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 08's texture layouts: "linear" again (rows, now with MIP levels and 8-bit
// texels) and "tiled", the default from this chapter on, and their options.
// Chapters 01 to 07 are registered first.
void register_chapter08(Registry& registry);

}  // namespace freezeray
