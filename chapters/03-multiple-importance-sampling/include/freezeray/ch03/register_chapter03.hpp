// What chapter 03 adds to the renderer.
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Registers chapter 03's lights ("area" for every emissive triangle, "point", "spot",
// "directional", "environment", "constant") and integrators ("pt-nee", "pt-mis" and their
// variants with uniform light selection and the balance heuristic).
// Chapters 01 to 02 are registered first.
void register_chapter03(Registry& registry);

}  // namespace freezeray
