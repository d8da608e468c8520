// What chapter 01 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers `pt-naive`.
void register_chapter01(Registry& registry);

}  // namespace freezeray
