// What chapter 05 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 05's integrators ("mlt", "mlt-multiplexed", "auto") and its rule for
// advising mlt.
// Chapters 01 to 04 are registered first.
void register_chapter05(Registry& registry);

}  // namespace freezeray
