// How a render chooses the one capability of a kind it uses (an accelerator, a sampler, a texture
// layout, a camera): the name the command line's selector gave, else the one the scene file's
// block names, else the catalogue's default. Every kind is chosen by this one rule
// (capability_catalogue.hpp's KindDescription says where each kind's selector and key are).
#pragma once

#include "freezeray/capability_catalogue.hpp"

#include <map>
#include <string>

namespace freezeray {

// The names given on the command line, by kind (each selector's value); a kind absent here was
// not given.
using Selections = std::map<CapabilityKind, std::string>;

struct CapabilityChoice {
    std::string name;   // empty when the catalogue is empty and nothing names one
    std::string where;  // where the name came from, for messages: "--accel", "scene.json: /accelerator/type"
    bool named = false; // by the command line or the scene, rather than the default
};

// The choice for `catalogue`'s kind: `selected`'s name for it, else `scene_value` (given at
// `scene_where`; empty: the scene names none), else the default. A name that is not registered is
// an InputError at its place.
CapabilityChoice choose_capability(const CatalogueBase& catalogue, const Selections& selected, const std::string& scene_value,
                                   const std::string& scene_where);

}  // namespace freezeray
