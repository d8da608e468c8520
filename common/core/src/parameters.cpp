// Typed, located access to JSON parameters.
#include "freezeray/parameters.hpp"

#include "freezeray/error.hpp"
#include "freezeray/registry.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace freezeray {

namespace {

const char* json_type_name(const nlohmann::json& j) {
    if (j.is_number()) return "a number";
    if (j.is_string()) return "a string";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    if (j.is_boolean()) return "a boolean";
    return "null";
}

}  // namespace

const Parameters& Parameters::none() {
    static const nlohmann::json empty = nlohmann::json::object();
    static const Parameters parameters(empty, "(defaults)", "", ".");
    return parameters;
}

Parameters::Parameters(const nlohmann::json& json, std::string file, std::string path, std::string base_directory)
    : json_(json), file_(std::move(file)), path_(std::move(path)), base_directory_(std::move(base_directory)) {
    if (!json_.is_object()) throw InputError(where(), std::string("expected an object, found ") + json_type_name(json_));
}

std::string Parameters::where() const { return file_ + ": " + (path_.empty() ? "/" : path_); }
std::string Parameters::where(const std::string& key) const {
    const auto it = locations_.find(key);
    return it != locations_.end() ? it->second : file_ + ": " + path_ + "/" + key;
}

const nlohmann::json* Parameters::find(const std::string& key) const {
    asked_.insert(key);
    const auto it = json_.find(key);
    return it == json_.end() ? nullptr : &*it;
}

bool Parameters::has(const std::string& key) const { return find(key) != nullptr; }

float Parameters::get_float(const std::string& key, float fallback) const {
    const nlohmann::json* j = find(key);
    if (!j) return fallback;
    if (!j->is_number()) throw InputError(where(key), std::string("expected a number, found ") + json_type_name(*j));
    const double value = j->get<double>();
    if (!std::isfinite(value) || std::abs(value) > 3.0e38)
        throw InputError(where(key), "the number is not finite in single precision");
    return static_cast<float>(value);
}

float Parameters::require_float(const std::string& key) const {
    if (!has(key)) throw InputError(where(key), "is required (a number)");
    return get_float(key, 0.0f);
}

int Parameters::get_int(const std::string& key, int fallback) const {
    const nlohmann::json* j = find(key);
    if (!j) return fallback;
    if (!j->is_number_integer())
        throw InputError(where(key), std::string("expected a whole number, found ") + json_type_name(*j));
    const auto value = j->get<long long>();
    if (value < INT32_MIN || value > INT32_MAX) throw InputError(where(key), "the number is out of range");
    return static_cast<int>(value);
}

long long Parameters::get_long(const std::string& key, long long fallback) const {
    const nlohmann::json* j = find(key);
    if (!j) return fallback;
    if (!j->is_number_integer())
        throw InputError(where(key), std::string("expected a whole number, found ") + json_type_name(*j));
    if (j->is_number_unsigned() && j->get<unsigned long long>() > static_cast<unsigned long long>(INT64_MAX))
        throw InputError(where(key), "the number is out of range");
    return j->get<long long>();
}

bool Parameters::get_bool(const std::string& key, bool fallback) const {
    const nlohmann::json* j = find(key);
    if (!j) return fallback;
    if (!j->is_boolean()) throw InputError(where(key), std::string("expected true or false, found ") + json_type_name(*j));
    return j->get<bool>();
}

std::string Parameters::get_string(const std::string& key, const std::string& fallback) const {
    const nlohmann::json* j = find(key);
    if (!j) return fallback;
    if (!j->is_string()) throw InputError(where(key), std::string("expected a string, found ") + json_type_name(*j));
    return j->get<std::string>();
}

std::string Parameters::require_string(const std::string& key) const {
    if (!has(key)) throw InputError(where(key), "is required (a string)");
    return get_string(key, "");
}

Vec3 Parameters::get_vec3(const std::string& key, const Vec3& fallback) const {
    const nlohmann::json* j = find(key);
    if (!j) return fallback;
    if (!j->is_array() || j->size() != 3)
        throw InputError(where(key), std::string("expected an array of 3 numbers, found ") + json_type_name(*j) +
                                         (j->is_array() ? " of " + std::to_string(j->size()) : std::string()));
    Vec3 v;
    for (int i = 0; i < 3; ++i) {
        const nlohmann::json& e = (*j)[static_cast<std::size_t>(i)];
        if (!e.is_number()) throw InputError(where(key) + "/" + std::to_string(i), "expected a number");
        const double value = e.get<double>();
        if (!std::isfinite(value) || std::abs(value) > 3.0e38)
            throw InputError(where(key) + "/" + std::to_string(i), "the number is not finite in single precision");
        v[i] = static_cast<float>(value);
    }
    return v;
}

Vec3 Parameters::require_vec3(const std::string& key) const {
    if (!has(key)) throw InputError(where(key), "is required (an array of 3 numbers)");
    return get_vec3(key, Vec3(0.0f));
}

Spectrum Parameters::get_spectrum(const std::string& key, const Spectrum& fallback) const {
    const nlohmann::json* j = find(key);
    if (j && j->is_number()) return Spectrum(get_float(key, 0.0f));
    return get_vec3(key, fallback);
}

std::string shared_scenes_folder() {
    if (const char* folder = std::getenv("FREEZERAY_SHARED_SCENES"); folder != nullptr && *folder != '\0') return folder;
    return FREEZERAY_DEFAULT_SHARED_SCENES;
}

std::string Parameters::require_existing_file(const std::string& key) const {
    const std::string name = require_string(key);
    static const std::string shared_prefix = "$FREEZERAY_SHARED_SCENES/";
    const bool shared = name.starts_with(shared_prefix);
    std::filesystem::path path = shared ? std::filesystem::path(shared_scenes_folder()) / name.substr(shared_prefix.size())
                                        : std::filesystem::path(name);
    if (path.is_relative()) path = std::filesystem::path(base_directory_) / path;
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw InputError(where(key), "file '" + path.lexically_normal().string() + "' does not exist" +
                                         (shared ? " (in the shared scenes folder: $FREEZERAY_SHARED_SCENES, or " +
                                                       std::string(FREEZERAY_DEFAULT_SHARED_SCENES) + " when it is unset)"
                                                 : ""));
    return path.lexically_normal().string();
}

Parameters Parameters::child(const std::string& key) const {
    const nlohmann::json* j = find(key);
    if (!j) throw InputError(where(key), "is required (an object)");
    return Parameters(*j, file_, path_ + "/" + key, base_directory_);
}

float Parameters::check_range(const std::string& key, float value, float min, float max) const {
    if (!(value >= min && value <= max))
        throw InputError(where(key), "value " + std::to_string(value) + " is outside [" + std::to_string(min) + ", " +
                                         std::to_string(max) + "]");
    return value;
}

std::vector<std::string> Parameters::unused_key_warnings() const {
    std::vector<std::string> warnings;
    const std::vector<std::string> known(asked_.begin(), asked_.end());
    for (const auto& [key, value] : json_.items()) {
        if (asked_.count(key)) continue;
        std::string message = where(key) + ": unknown key '" + key + "' is ignored";
        if (!known.empty()) message += " (did you mean '" + nearest_name(key, known) + "'?)";
        warnings.push_back(message);
    }
    return warnings;
}

}  // namespace freezeray
