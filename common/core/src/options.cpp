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
                         OptionTarget target, const std::vector<std::string>& chosen, const std::string& role) {
    auto listed = [](const std::vector<std::string>& names) {
        std::string text;
        for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
        return text;
    };
    for (const OptionDeclaration& d : declarations) {
        if (d.target != target || !given.values.contains(d.key) || d.used_by.empty()) continue;
        const bool read = std::any_of(chosen.begin(), chosen.end(), [&](const std::string& name) {
            return std::find(d.used_by.begin(), d.used_by.end(), name) != d.used_by.end();
        });
        if (read) continue;
        throw InputError(d.flag, "is an option of " + listed(d.used_by) + ", not of " + listed(chosen) + " (" + role + ")");
    }
}

void check_options_apply(const OptionValues& given, const std::vector<OptionDeclaration>& declarations,
                         OptionTarget target, const std::string& chosen) {
    check_options_apply(given, declarations, target, std::vector<std::string>{chosen},
                        target == OptionTarget::Integrator ? "this render's integrator" : "this render's accelerator");
}

}  // namespace freezeray
