// What every catalogue of capabilities does alike.
#include "freezeray/capability_catalogue.hpp"

#include "freezeray/error.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>

namespace freezeray {

const KindDescription& kind_description(CapabilityKind kind) {
    // The selectors and scene keys are the ones the command line (cli.cpp) and the scene format
    // (scenes/README.md) use.
    static const KindDescription kinds[] = {
        {CapabilityKind::Integrator, "integrator", "--integrator", "render", "integrator", "how light is transported", false},
        {CapabilityKind::Material, "material", "", "", "", "", false},
        {CapabilityKind::Accelerator, "accelerator", "--accel", "accelerator", "type", "the ray-intersection accelerator",
         false},
        {CapabilityKind::Light, "light", "", "", "", "", false},
        {CapabilityKind::TextureLayout, "texture layout", "--texture-layout", "textures", "layout",
         "how image textures are stored", false},
        {CapabilityKind::Sampler, "sampler", "--sampler", "render", "sampler",
         "where the per-pixel integrators' numbers come from", true},
        {CapabilityKind::LightSampler, "light sampler", "--light-sampler", "render", "light_sampler",
         "how the integrators that sample lights choose one at a shading point", true},
        {CapabilityKind::Camera, "camera", "", "camera", "type", "how rays leave the camera", false},
    };
    for (const KindDescription& k : kinds)
        if (k.kind == kind) return k;
    throw std::logic_error("a capability kind without a description");
}

const char* capability_kind_name(CapabilityKind kind) { return kind_description(kind).name; }

int RendererIdentity::chapter_introducing(CapabilityKind kind, const std::string& name) const {
    if (table_of_contents == nullptr) return 0;
    for (const CatalogueEntry& entry : *table_of_contents)
        if (entry.kind == kind && name == entry.name) return entry.chapter;
    return 0;
}

std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates) {
    // Levenshtein distance with one row of the dynamic-programming table (Wagner and Fischer 1974).
    auto distance = [](const std::string& a, const std::string& b) {
        std::vector<std::size_t> row(b.size() + 1);
        std::iota(row.begin(), row.end(), std::size_t{0});
        for (std::size_t i = 1; i <= a.size(); ++i) {
            std::size_t diagonal = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= b.size(); ++j) {
                const std::size_t above = row[j];
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
                diagonal = above;
            }
        }
        return row[b.size()];
    };
    std::string best;
    std::size_t best_distance = SIZE_MAX;
    for (const std::string& c : candidates) {
        // A candidate that contains what was typed ("fov" in "fov_vertical_degrees") is a
        // better guess than any short unrelated word.
        const bool contains = !name.empty() && c.find(name) != std::string::npos;
        const std::size_t d = contains ? c.size() - name.size() : (SIZE_MAX / 2) + distance(name, c);
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

std::vector<CapabilityEntry> CatalogueBase::list() const {
    std::vector<CapabilityEntry> entries;
    for (const auto& [name, entry] : entries_) entries.push_back(entry);
    return entries;
}

void CatalogueBase::add_entry(const std::string& name, int chapter, const std::string& summary) {
    const auto existing = entries_.find(name);
    const int introduced = existing != entries_.end() ? existing->second.introduced_in : chapter;
    entries_[name] = CapabilityEntry{name, chapter, summary, introduced};
    if (default_.empty()) default_ = name;
}

void CatalogueBase::set_default(const std::string& name) {
    if (!has(name))
        throw std::logic_error(std::string("default ") + description().name + " '" + name + "' is not registered");
    default_ = name;
}

void CatalogueBase::require(const std::string& name, const std::string& where) const {
    if (!has(name)) unknown(name, where);
}

void CatalogueBase::unknown(const std::string& name, const std::string& where) const {
    const std::string kind_name = description().name;
    const std::string& program = renderer_->program;
    const int last = renderer_->chapter;
    const auto two_digits = [](int chapter) { return (chapter < 10 ? "0" : "") + std::to_string(chapter); };
    const int chapter = renderer_->chapter_introducing(kind_, name);
    if (chapter > last)
        throw InputError(where, kind_name + " '" + name + "' is introduced in chapter " + two_digits(chapter) +
                                    "; this renderer (" + program + ") goes up to chapter " + two_digits(last) +
                                    " (the complete renderer is `freezeray`)");
    if (chapter > 0)  // a chapter up to this renderer's last that it does not contain (not written yet)
        throw InputError(where, kind_name + " '" + name + "' is introduced in chapter " + two_digits(chapter) +
                                    ", which this renderer (" + program +
                                    ") does not contain: that chapter is not written yet");
    std::vector<std::string> names;
    for (const CapabilityEntry& e : list()) names.push_back(e.name);
    std::string message = "unknown " + kind_name + " '" + name + "'";
    if (!names.empty()) message += " (did you mean '" + nearest_name(name, names) + "'?)";
    std::string all;
    for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
    message += "; " + program + " knows: " + all;
    throw InputError(where, message);
}

}  // namespace freezeray
