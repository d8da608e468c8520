// What chapter 10 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 10's light samplers ("bvh", the tree with a defensive share of uniform
// choices, and "bvh-tree", the tree alone) and makes "bvh" the default light sampler.
// Chapters 01 to 09 are registered first.
void register_chapter10(Registry& registry);

}  // namespace freezeray
