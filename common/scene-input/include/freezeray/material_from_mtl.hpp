// Which renderer material an MTL block stands for.
#pragma once

#include "freezeray/obj_loader.hpp"

#include <nlohmann/json.hpp>

namespace freezeray {

// The JSON description (as in a scene's "materials" block) of the material an MTL block
// describes; JSON overrides are applied to it by name. The mapping (scenes/README.md):
//   illum 4, 6, 7              -> dielectric (Ni), rough when Pr > 0
//   Pm > 0.5 (PBR metal)       -> conductor tinted by Kd / map_Kd, rough when Pr or Ns says so
//   illum 3, 5                 -> conductor tinted by Ks / map_Ks, rough likewise
//   Ks > 0                     -> plastic with albedo Kd / map_Kd, rough likewise
//   otherwise                  -> diffuse with albedo Kd / map_Kd
// plus emission Ke. Types a chapter has not registered are reported with the chapter that adds
// them when the material is built.
nlohmann::json material_from_mtl(const MtlMaterial& mtl);

// The roughness (alpha = roughness^2) equivalent to a Phong exponent Ns: alpha = sqrt(2 / (Ns + 2))
// (Walter, Marschner, Li and Torrance, "Microfacet Models for Refraction through Rough
// Surfaces", EGSR 2007, section 5.2), so roughness = (2 / (Ns + 2))^(1/4).
float roughness_from_phong_exponent(float ns);

}  // namespace freezeray
