// Typed, located access to a JSON object of parameters (a material, the camera, render
// defaults). Every error names the file and the JSON path; unknown keys produce a warning
// with the nearest valid name.
#pragma once

#include "freezeray/math.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace freezeray {

// The folder of the large public scenes that are not in the repository: the environment
// variable FREEZERAY_SHARED_SCENES, or when it is unset the folder shared/scenes beside the
// checkout (../shared/scenes from the repository's root).
std::string shared_scenes_folder();

class Parameters {
public:
    // json: the object; file: the scene file; path: JSON pointer of the object ("/materials/light");
    // base_directory: where relative file names are resolved.
    Parameters(const nlohmann::json& json, std::string file, std::string path, std::string base_directory);
    // No parameters at all: every setting at its default (a capability made without a scene block).
    static const Parameters& none();

    const std::string& file() const { return file_; }
    const std::string& path() const { return path_; }
    const std::string& base_directory() const { return base_directory_; }
    // "scene.json: /materials/light/albedo" for a key of this object.
    std::string where(const std::string& key) const;
    std::string where() const;
    // Says that `key` was given somewhere else than in this object (a command-line flag): messages
    // about it then name that place.
    void set_location(const std::string& key, std::string location) { locations_[key] = std::move(location); }

    bool has(const std::string& key) const;
    float get_float(const std::string& key, float fallback) const;
    float require_float(const std::string& key) const;
    int get_int(const std::string& key, int fallback) const;
    // A whole number that may exceed 32 bits (a sample count).
    long long get_long(const std::string& key, long long fallback) const;
    bool get_bool(const std::string& key, bool fallback) const;
    std::string get_string(const std::string& key, const std::string& fallback) const;
    std::string require_string(const std::string& key) const;
    Vec3 get_vec3(const std::string& key, const Vec3& fallback) const;
    Vec3 require_vec3(const std::string& key) const;
    // A colour given as [r, g, b] or a single number (grey).
    Spectrum get_spectrum(const std::string& key, const Spectrum& fallback) const;
    // A path relative to the base directory, resolved and checked to exist. A name beginning
    // with "$FREEZERAY_SHARED_SCENES/" is in the shared scenes folder (shared_scenes_folder()).
    std::string require_existing_file(const std::string& key) const;
    Parameters child(const std::string& key) const;  // a nested object (must exist)
    const nlohmann::json& json() const { return json_; }

    // Warnings for keys that no getter asked for, each with the nearest key that was asked for.
    // Call after reading everything.
    std::vector<std::string> unused_key_warnings() const;

    // Floats must be finite; this also checks a range and names the place.
    float check_range(const std::string& key, float value, float min, float max) const;

private:
    const nlohmann::json* find(const std::string& key) const;

    const nlohmann::json& json_;
    std::string file_;
    std::string path_;
    std::string base_directory_;
    mutable std::set<std::string> asked_;
    std::map<std::string, std::string> locations_;
};

}  // namespace freezeray
