// Which renderer material an MTL block stands for.
#include "freezeray/material_from_mtl.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace freezeray {

float roughness_from_phong_exponent(float ns) { return std::pow(2.0f / (std::max(ns, 0.0f) + 2.0f), 0.25f); }

namespace {

nlohmann::json colour(const Spectrum& c) { return {c.r, c.g, c.b}; }

// The roughness an MTL block states: Pr (PBR extension) first, else one derived from Ns, else
// none (a smooth surface).
std::optional<float> stated_roughness(const MtlMaterial& m) {
    if (m.pr.has_value()) return *m.pr;
    if (m.ns > 0.0f) return roughness_from_phong_exponent(m.ns);
    return std::nullopt;
}

}  // namespace

nlohmann::json material_from_mtl(const MtlMaterial& m) {
    nlohmann::json j;
    const std::optional<float> roughness = stated_roughness(m);
    const bool rough = (roughness.has_value() && *roughness > 0.0f) || !m.map_pr.empty();
    auto add_roughness = [&] {
        if (!m.map_pr.empty()) {
            j["roughness_texture"] = m.map_pr;
        } else if (roughness.has_value()) {
            j["roughness"] = *roughness;
        }
    };
    if (m.illum == 4 || m.illum == 6 || m.illum == 7) {
        j["type"] = m.pr.has_value() && *m.pr > 0.0f ? "roughdielectric" : "dielectric";
        j["ior"] = m.ni;
        if (j["type"] == "roughdielectric") j["roughness"] = *m.pr;
    } else if (m.pm.has_value() && *m.pm > 0.5f) {
        // A PBR metal: its base colour is the reflectance at normal incidence. The PBR extension
        // writes it as Kd; files that keep the classic metal (illum 3, reflectance in Ks) and add
        // Pm leave Kd black, as the Bitterli scenes' conversions do: then Ks is the colour.
        j["type"] = rough ? "roughconductor" : "conductor";
        const bool colour_in_ks = is_black(m.kd) && m.map_kd.empty() && (!is_black(m.ks) || !m.map_ks.empty());
        j["specular_reflectance"] = colour(colour_in_ks ? m.ks : m.kd);
        if (!colour_in_ks && !m.map_kd.empty()) j["specular_reflectance_texture"] = m.map_kd;
        if (colour_in_ks && !m.map_ks.empty()) j["specular_reflectance_texture"] = m.map_ks;
        if (rough) add_roughness();
    } else if (m.illum == 3 || m.illum == 5) {
        j["type"] = rough ? "roughconductor" : "conductor";
        j["specular_reflectance"] = colour(m.ks);
        if (!m.map_ks.empty()) j["specular_reflectance_texture"] = m.map_ks;
        if (rough) add_roughness();
    } else if (max_component(m.ks) > 0.0f) {
        j["type"] = rough ? "roughplastic" : "plastic";
        j["albedo"] = colour(m.kd);
        if (!m.map_kd.empty()) j["albedo_texture"] = m.map_kd;
        j["ior"] = m.ni;
        if (rough) add_roughness();
    } else {
        j["type"] = "diffuse";
        j["albedo"] = colour(m.kd);
        if (!m.map_kd.empty()) j["albedo_texture"] = m.map_kd;
    }
    if (!is_black(m.ke)) j["emission"] = colour(m.ke);
    // An alpha mask cuts holes into the surface (chapter 02 reads it; see AlphaMask).
    if (!m.map_d.empty()) j["alpha_texture"] = m.map_d;
    return j;
}

}  // namespace freezeray
