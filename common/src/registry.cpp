// The registry, and the course catalogue used for "introduced in chapter N" messages.
#include "freezeray/registry.hpp"

#include "freezeray/error.hpp"
#include "freezeray/lambertian.hpp"

#include <algorithm>
#include <numeric>

namespace freezeray {

const char* capability_kind_name(CapabilityKind kind) {
    switch (kind) {
        case CapabilityKind::Integrator: return "integrator";
        case CapabilityKind::Material: return "material";
        case CapabilityKind::Accelerator: return "accelerator";
        case CapabilityKind::Light: return "light";
        case CapabilityKind::TextureLayout: return "texture layout";
    }
    return "capability";
}

// Every name the course introduces, with its chapter, including chapters a renderer may have
// been built without. A chapter that adds a capability adds its line here too.
int chapter_introducing(CapabilityKind kind, const std::string& name) {
    struct Known {
        CapabilityKind kind;
        const char* name;
        int chapter;
    };
    static const Known catalogue[] = {
        {CapabilityKind::Integrator, "pt-naive", 1},
        {CapabilityKind::Material, "diffuse", 1},
        {CapabilityKind::Accelerator, "bruteforce", 1},
        {CapabilityKind::Integrator, "pt-is", 2},
        {CapabilityKind::Material, "mirror", 2},
        {CapabilityKind::Material, "conductor", 2},
        {CapabilityKind::Material, "roughconductor", 2},
        {CapabilityKind::Material, "dielectric", 2},
        {CapabilityKind::Material, "roughdielectric", 2},
        {CapabilityKind::Material, "plastic", 2},
        {CapabilityKind::Material, "roughplastic", 2},
        {CapabilityKind::Material, "mix", 2},
        {CapabilityKind::TextureLayout, "linear", 2},
        {CapabilityKind::Integrator, "pt-nee", 3},
        {CapabilityKind::Integrator, "pt-nee-uniform", 3},
        {CapabilityKind::Integrator, "pt-mis", 3},
        {CapabilityKind::Integrator, "pt-mis-balance", 3},
        {CapabilityKind::Integrator, "pt-mis-uniform", 3},
        {CapabilityKind::Light, "area", 3},
        {CapabilityKind::Light, "point", 3},
        {CapabilityKind::Light, "spot", 3},
        {CapabilityKind::Light, "directional", 3},
        {CapabilityKind::Light, "environment", 3},
        {CapabilityKind::Light, "constant", 3},
        {CapabilityKind::Integrator, "bdpt", 4},
        {CapabilityKind::Integrator, "light-tracing", 4},
        {CapabilityKind::Integrator, "mlt", 5},
        {CapabilityKind::Accelerator, "kdtree", 6},
        {CapabilityKind::Accelerator, "kdtree-simd", 7},
        {CapabilityKind::TextureLayout, "tiled", 8},
    };
    for (const Known& k : catalogue)
        if (k.kind == kind && name == k.name) return k.chapter;
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

Registry::Registry(std::string program, int chapter) : program_(std::move(program)), chapter_(chapter) {
    add_material("diffuse", 1, "Lambertian reflector: albedo (MTL Kd)", [](const Parameters& p) {
        const Spectrum albedo = p.get_spectrum("albedo", Spectrum(0.5f));
        for (int c = 0; c < 3; ++c) p.check_range("albedo", albedo[c], 0.0f, 1.0f);
        return std::make_unique<DiffuseMaterial>(albedo);
    });
    add_accelerator("bruteforce", 1, "every triangle of every mesh whose bounding box the ray meets",
                    [] { return std::make_unique<BruteForceAccelerator>(); });
}

void Registry::add_integrator(const std::string& name, int chapter, const std::string& summary, IntegratorFactory f) {
    integrators_[name] = {Entry{name, chapter, summary}, std::move(f)};
}
void Registry::add_material(const std::string& name, int chapter, const std::string& summary, MaterialFactory f) {
    materials_[name] = {Entry{name, chapter, summary}, std::move(f)};
}
void Registry::add_accelerator(const std::string& name, int chapter, const std::string& summary, AcceleratorFactory f) {
    accelerators_[name] = {Entry{name, chapter, summary}, std::move(f)};
}

void Registry::add_light(const std::string& name, int chapter, const std::string& summary, LightFactory f) {
    lights_[name] = {Entry{name, chapter, summary}, std::move(f)};
}
void Registry::add_area_light(int chapter, const std::string& summary, AreaLightFactory f) {
    area_light_ = {Entry{"area", chapter, summary}, std::move(f)};
}

bool Registry::has(CapabilityKind kind, const std::string& name) const {
    switch (kind) {
        case CapabilityKind::Integrator: return integrators_.count(name) > 0;
        case CapabilityKind::Material: return materials_.count(name) > 0;
        case CapabilityKind::Accelerator: return accelerators_.count(name) > 0;
        case CapabilityKind::Light: return lights_.count(name) > 0 || (name == "area" && area_light_.has_value());
        default: return false;
    }
}

std::vector<Registry::Entry> Registry::list(CapabilityKind kind) const {
    std::vector<Entry> entries;
    auto collect = [&](const auto& map) {
        for (const auto& [name, entry] : map) entries.push_back(entry.first);
    };
    if (kind == CapabilityKind::Integrator) collect(integrators_);
    if (kind == CapabilityKind::Material) collect(materials_);
    if (kind == CapabilityKind::Accelerator) collect(accelerators_);
    if (kind == CapabilityKind::Light) {
        collect(lights_);
        if (area_light_) entries.push_back(area_light_->first);
        std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
    }
    return entries;
}

void Registry::unknown(CapabilityKind kind, const std::string& name, const std::string& where) const {
    const std::string kind_name = capability_kind_name(kind);
    const int chapter = chapter_introducing(kind, name);
    if (chapter > chapter_)
        throw InputError(where, kind_name + " '" + name + "' is introduced in chapter " +
                                    (chapter < 10 ? "0" : "") + std::to_string(chapter) + "; this renderer (" +
                                    program_ + ") goes up to chapter " + (chapter_ < 10 ? "0" : "") +
                                    std::to_string(chapter_) + " (the complete renderer is `freezeray`)");
    std::vector<std::string> names;
    for (const Entry& e : list(kind)) names.push_back(e.name);
    std::string message = "unknown " + kind_name + " '" + name + "'";
    if (!names.empty()) message += " (did you mean '" + nearest_name(name, names) + "'?)";
    std::string all;
    for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
    message += "; " + program_ + " knows: " + all;
    throw InputError(where, message);
}

std::unique_ptr<Integrator> Registry::make_integrator(const std::string& name, const RenderSettings& settings,
                                                      const std::string& where) const {
    const auto it = integrators_.find(name);
    if (it == integrators_.end()) unknown(CapabilityKind::Integrator, name, where);
    return it->second.second(settings);
}

std::unique_ptr<Material> Registry::make_material(const std::string& type, const Parameters& parameters) const {
    const auto it = materials_.find(type);
    if (it == materials_.end()) unknown(CapabilityKind::Material, type, parameters.where("type"));
    return it->second.second(parameters);
}

std::unique_ptr<Accelerator> Registry::make_accelerator(const std::string& name, const std::string& where) const {
    const auto it = accelerators_.find(name);
    if (it == accelerators_.end()) unknown(CapabilityKind::Accelerator, name, where);
    return it->second.second();
}

std::unique_ptr<Light> Registry::make_light(const std::string& type, const Parameters& parameters) const {
    const auto it = lights_.find(type);
    if (it == lights_.end()) unknown(CapabilityKind::Light, type, parameters.where("type"));
    return it->second.second(parameters);
}

std::unique_ptr<Light> Registry::make_area_light(const TriangleMesh& mesh, std::uint32_t triangle,
                                                 const Spectrum& emission) const {
    if (!area_light_) return nullptr;
    return area_light_->second(mesh, triangle, emission);
}

}  // namespace freezeray
