// Options declared by chapters: merging command-line values over the scene's, and refusing a
// flag that the chosen capability does not read.
#include "freezeray/options.hpp"

#include "freezeray/error.hpp"

#include <algorithm>

namespace freezeray {

OptionParameters::OptionParameters(const nlohmann::json* scene_block, const std::string& file, const std::string& path,
                                   const std::string& base_directory, const OptionValues& given,
                                   const std::vector<OptionDeclaration>& declarations, OptionTarget target)
    : json_(scene_block != nullptr ? *scene_block : nlohmann::json::object()),  // Parameters refuses a non-object
      parameters_(json_, file, path, base_directory) {
    for (const OptionDeclaration& d : declarations) {
        if (d.target != target) continue;
        const auto value = given.values.find(d.key);
        if (value == given.values.end()) continue;
        json_[d.key] = *value;  // the command line wins over the scene file
        const auto flag = given.flags.find(d.key);
        parameters_.set_location(d.key, flag != given.flags.end() ? flag->second : d.flag);
    }
}

std::string option_default_text(double value) {
    std::string text = std::to_string(value);
    text.erase(text.find_last_not_of('0') + 1);  // "0.300000" -> "0.3"
    if (!text.empty() && text.back() == '.') text.pop_back();
    return text;
}

void check_options_apply(const OptionValues& given, const std::vector<OptionDeclaration>& declarations,
                         OptionTarget target, const std::string& chosen) {
    for (const OptionDeclaration& d : declarations) {
        if (d.target != target || !given.values.contains(d.key) || d.used_by.empty()) continue;
        if (std::find(d.used_by.begin(), d.used_by.end(), chosen) != d.used_by.end()) continue;
        std::string users;
        for (const std::string& u : d.used_by) users += (users.empty() ? "" : ", ") + u;
        throw InputError(d.flag, "is an option of " + users + ", not of " + chosen + " (this render's " +
                                     (target == OptionTarget::Integrator ? "integrator" : "accelerator") + ")");
    }
}

}  // namespace freezeray
