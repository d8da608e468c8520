// The one rule by which a render chooses a capability of each kind.
#include "freezeray/capability_choice.hpp"

namespace freezeray {

CapabilityChoice choose_capability(const CatalogueBase& catalogue, const Selections& selected, const std::string& scene_value,
                                   const std::string& scene_where) {
    CapabilityChoice choice;
    if (const auto it = selected.find(catalogue.kind()); it != selected.end() && !it->second.empty()) {
        choice = {it->second, catalogue.description().selector, true};
    } else if (!scene_value.empty()) {
        choice = {scene_value, scene_where, true};
    } else {
        choice = {catalogue.default_name(), std::string("the default ") + catalogue.description().name, false};
        if (choice.name.empty()) return choice;
    }
    catalogue.require(choice.name, choice.where);
    return choice;
}

}  // namespace freezeray
