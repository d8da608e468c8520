// What chapter 02 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 02's materials: "diffuse" (replacing chapter 01's with a textured,
// cosine-sampled one), "mirror", "conductor", "roughconductor", "dielectric",
// "roughdielectric", "plastic", "roughplastic" and "mix".
// Chapter 01 is registered first.
void register_chapter02(Registry& registry);

}  // namespace freezeray
