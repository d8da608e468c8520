// Options that a chapter declares for its capabilities (an integrator's step size, a folder for
// its extra images, an accelerator's costs). common/ knows none of them: a chapter adds each
// through Registry::add_option, the command line offers exactly the registered ones, and the
// value reaches the capability's factory as a key of its Parameters, after the scene's own value
// for that key (the scene's "render" block for integrators, its "accelerator" block for
// accelerators, its "textures" block for texture layouts).
#pragma once

#include "freezeray/parameters.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace freezeray {

// Which capability reads an option, and so which block of the scene file holds its value.
enum class OptionTarget { Integrator, Accelerator, Textures };

// The type of an option's value: a number, a whole number, a text (a name, a folder), or a flag
// that is either given or not (true when given).
enum class OptionType { Number, Integer, Text, Flag };

struct OptionDeclaration {
    std::string flag;   // on the command line: "--some-setting"
    std::string key;    // in the scene file and in Parameters: "some_setting"
    OptionType type = OptionType::Number;
    OptionTarget target = OptionTarget::Integrator;
    std::string help;   // one line for --help (with the default)
    // The capabilities (of `target`'s kind) that read it; a flag given to a render that uses
    // none of them is refused, so that a mistyped integrator does not silently drop an option.
    std::vector<std::string> used_by;
    int chapter = 0;
};

// The values of registered options given on the command line, by key.
struct OptionValues {
    nlohmann::json values = nlohmann::json::object();
    std::map<std::string, std::string> flags;  // key -> the flag that gave it, for messages
};

// A capability's parameters: the scene block's keys (`scene_block`, which may be null), with the
// command-line values of options of `target` given over them. The result owns its JSON, so it
// outlives the scene's.
class OptionParameters {
public:
    OptionParameters(const nlohmann::json* scene_block, const std::string& file, const std::string& path,
                     const std::string& base_directory, const OptionValues& given,
                     const std::vector<OptionDeclaration>& declarations, OptionTarget target);
    OptionParameters(const OptionParameters&) = delete;
    OptionParameters& operator=(const OptionParameters&) = delete;

    const Parameters& parameters() const { return parameters_; }

private:
    nlohmann::json json_;
    Parameters parameters_;
};

// A default value as an option's help shows it: "0.3", not "0.300000".
std::string option_default_text(double value);

// Refuses (InputError at the flag) an option given on the command line whose capabilities do not
// include `chosen` (the integrator or accelerator this run uses).
void check_options_apply(const OptionValues& given, const std::vector<OptionDeclaration>& declarations,
                         OptionTarget target, const std::string& chosen);

// The same for a run that uses several capabilities of `target`'s kind (a benchmark measuring
// several accelerators): an option is refused when none of `chosen` reads it; `role` names them
// in the message ("the accelerators measured").
void check_options_apply(const OptionValues& given, const std::vector<OptionDeclaration>& declarations,
                         OptionTarget target, const std::vector<std::string>& chosen, const std::string& role);

}  // namespace freezeray
