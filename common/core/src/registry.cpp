// The registry of capabilities by name.
#include "freezeray/registry.hpp"

#include "freezeray/error.hpp"

#include <algorithm>
#include <stdexcept>
#include <numeric>

namespace freezeray {

const char* capability_kind_name(CapabilityKind kind) {
    switch (kind) {
        case CapabilityKind::Integrator: return "integrator";
        case CapabilityKind::Material: return "material";
        case CapabilityKind::Accelerator: return "accelerator";
        case CapabilityKind::Light: return "light";
        case CapabilityKind::TextureLayout: return "texture layout";
        case CapabilityKind::Sampler: return "sampler";
        case CapabilityKind::LightSampler: return "light sampler";
    }
    return "capability";
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
    add_accelerator("bruteforce", 1, "every triangle of every mesh whose bounding box the ray meets",
                    [](const Parameters&) { return std::make_unique<BruteForceAccelerator>(); });
    add_sampler("independent", 1, "independent uniform numbers, one PCG32 stream per pixel sample",
                [](const Parameters&) { return std::make_unique<IndependentSampler>(); });
}

namespace {

// Adds or replaces `name` in `map`; a replacement remembers the chapter that introduced the name
// (chapter 02's cosine-sampled "diffuse" replaces chapter 01's, which introduced it).
template <typename Factory>
void add_entry(std::map<std::string, std::pair<Registry::Entry, Factory>>& map, const std::string& name, int chapter,
               const std::string& summary, Factory factory) {
    const auto existing = map.find(name);
    const int introduced = existing != map.end() ? existing->second.first.introduced_in : chapter;
    map[name] = {Registry::Entry{name, chapter, summary, introduced}, std::move(factory)};
}

}  // namespace

void Registry::add_integrator(const std::string& name, int chapter, const std::string& summary, IntegratorFactory f) {
    add_entry(integrators_, name, chapter, summary, std::move(f));
}
void Registry::add_material(const std::string& name, int chapter, const std::string& summary, MaterialFactory f) {
    add_entry(materials_, name, chapter, summary, std::move(f));
}
void Registry::add_accelerator(const std::string& name, int chapter, const std::string& summary, AcceleratorFactory f) {
    add_entry(accelerators_, name, chapter, summary, std::move(f));
}

void Registry::add_light(const std::string& name, int chapter, const std::string& summary, LightFactory f) {
    add_entry(lights_, name, chapter, summary, std::move(f));
}
void Registry::add_area_light(int chapter, const std::string& summary, AreaLightFactory f) {
    area_light_ = {Entry{"area", chapter, summary, chapter}, std::move(f)};
}
void Registry::add_texture_layout(const std::string& name, int chapter, const std::string& summary,
                                  TextureLayoutFactory f) {
    add_entry(texture_layouts_, name, chapter, summary, std::move(f));
    if (default_texture_layout_.empty()) default_texture_layout_ = name;
}

void Registry::add_sampler(const std::string& name, int chapter, const std::string& summary, SamplerFactory f) {
    add_entry(samplers_, name, chapter, summary, std::move(f));
}

void Registry::add_light_sampler(const std::string& name, int chapter, const std::string& summary, LightSamplerFactory f) {
    add_entry(light_samplers_, name, chapter, summary, std::move(f));
    if (default_light_sampler_.empty()) default_light_sampler_ = name;
}

void Registry::add_option(OptionDeclaration option) {
    for (const OptionDeclaration& o : options_)
        if (o.flag == option.flag || (o.key == option.key && o.target == option.target))
            throw std::logic_error("option " + option.flag + " is declared twice");
    options_.push_back(std::move(option));
}

void Registry::add_option_user(const std::string& flag, const std::string& capability) {
    for (OptionDeclaration& o : options_)
        if (o.flag == flag) {
            if (std::find(o.used_by.begin(), o.used_by.end(), capability) == o.used_by.end()) o.used_by.push_back(capability);
            return;
        }
    throw std::logic_error("option " + flag + " is not declared");
}

void Registry::set_default_accelerator(const std::string& name) {
    if (!accelerators_.count(name)) throw std::logic_error("default accelerator '" + name + "' is not registered");
    default_accelerator_ = name;
}
void Registry::set_default_texture_layout(const std::string& name) {
    if (!texture_layouts_.count(name)) throw std::logic_error("default texture layout '" + name + "' is not registered");
    default_texture_layout_ = name;
}

void Registry::set_default_sampler(const std::string& name) {
    if (!samplers_.count(name)) throw std::logic_error("default sampler '" + name + "' is not registered");
    default_sampler_ = name;
}

void Registry::set_default_light_sampler(const std::string& name) {
    if (!light_samplers_.count(name)) throw std::logic_error("default light sampler '" + name + "' is not registered");
    default_light_sampler_ = name;
}

bool Registry::has(CapabilityKind kind, const std::string& name) const {
    switch (kind) {
        case CapabilityKind::Integrator: return integrators_.count(name) > 0;
        case CapabilityKind::Material: return materials_.count(name) > 0;
        case CapabilityKind::Accelerator: return accelerators_.count(name) > 0;
        case CapabilityKind::Light: return lights_.count(name) > 0 || (name == "area" && area_light_.has_value());
        case CapabilityKind::TextureLayout: return texture_layouts_.count(name) > 0;
        case CapabilityKind::Sampler: return samplers_.count(name) > 0;
        case CapabilityKind::LightSampler: return light_samplers_.count(name) > 0;
    }
    return false;  // not reached: every kind is handled above
}

void Registry::require(CapabilityKind kind, const std::string& name, const std::string& where) const {
    if (!has(kind, name)) unknown(kind, name, where);
}

std::vector<Registry::Entry> Registry::list(CapabilityKind kind) const {
    std::vector<Entry> entries;
    auto collect = [&](const auto& map) {
        for (const auto& [name, entry] : map) entries.push_back(entry.first);
    };
    if (kind == CapabilityKind::Integrator) collect(integrators_);
    if (kind == CapabilityKind::Material) collect(materials_);
    if (kind == CapabilityKind::Accelerator) collect(accelerators_);
    if (kind == CapabilityKind::TextureLayout) collect(texture_layouts_);
    if (kind == CapabilityKind::Sampler) collect(samplers_);
    if (kind == CapabilityKind::LightSampler) collect(light_samplers_);
    if (kind == CapabilityKind::Light) {
        collect(lights_);
        if (area_light_) entries.push_back(area_light_->first);
        std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
    }
    return entries;
}

void Registry::set_catalogue(const std::vector<CatalogueEntry>& catalogue) { catalogue_ = &catalogue; }

int Registry::chapter_introducing(CapabilityKind kind, const std::string& name) const {
    if (catalogue_ == nullptr) return 0;
    for (const CatalogueEntry& entry : *catalogue_)
        if (entry.kind == kind && name == entry.name) return entry.chapter;
    return 0;
}

void Registry::unknown(CapabilityKind kind, const std::string& name, const std::string& where) const {
    const std::string kind_name = capability_kind_name(kind);
    const int chapter = chapter_introducing(kind, name);
    if (chapter > chapter_)
        throw InputError(where, kind_name + " '" + name + "' is introduced in chapter " +
                                    (chapter < 10 ? "0" : "") + std::to_string(chapter) + "; this renderer (" +
                                    program_ + ") goes up to chapter " + (chapter_ < 10 ? "0" : "") +
                                    std::to_string(chapter_) + " (the complete renderer is `freezeray`)");
    if (chapter > 0)  // a chapter up to this renderer's last that it does not contain (not written yet)
        throw InputError(where, kind_name + " '" + name + "' is introduced in chapter " + (chapter < 10 ? "0" : "") +
                                    std::to_string(chapter) + ", which this renderer (" + program_ +
                                    ") does not contain: that chapter is not written yet");
    std::vector<std::string> names;
    for (const Entry& e : list(kind)) names.push_back(e.name);
    std::string message = "unknown " + kind_name + " '" + name + "'";
    if (!names.empty()) message += " (did you mean '" + nearest_name(name, names) + "'?)";
    std::string all;
    for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
    message += "; " + program_ + " knows: " + all;
    throw InputError(where, message);
}

namespace {

// The parameters of a capability made without any: every setting at its default.
const Parameters& no_parameters() {
    static const nlohmann::json empty = nlohmann::json::object();
    static const Parameters parameters(empty, "(defaults)", "", ".");
    return parameters;
}

}  // namespace

std::unique_ptr<Integrator> Registry::make_integrator(const std::string& name, const RenderSettings& settings,
                                                      const std::string& where, const Parameters* options) const {
    const auto it = integrators_.find(name);
    if (it == integrators_.end()) unknown(CapabilityKind::Integrator, name, where);
    return it->second.second(settings, options != nullptr ? *options : no_parameters());
}

IntegratorFactory Registry::integrator_factory(const std::string& name) const {
    const auto it = integrators_.find(name);
    return it != integrators_.end() ? it->second.second : IntegratorFactory{};
}

std::unique_ptr<Material> Registry::make_material(const std::string& type, const Parameters& parameters) const {
    return make_material(type, parameters, MaterialContext{*this, default_texture_layout_});
}

std::unique_ptr<Material> Registry::make_material(const std::string& type, const Parameters& parameters,
                                                  const MaterialContext& context) const {
    const auto it = materials_.find(type);
    if (it == materials_.end()) unknown(CapabilityKind::Material, type, parameters.where("type"));
    return it->second.second(parameters, context);
}

std::unique_ptr<Accelerator> Registry::make_accelerator(const std::string& name, const std::string& where,
                                                        const Parameters* options) const {
    const auto it = accelerators_.find(name);
    if (it == accelerators_.end()) unknown(CapabilityKind::Accelerator, name, where);
    return it->second.second(options != nullptr ? *options : no_parameters());
}

TextureStorageMaker Registry::texture_storage_maker(const std::string& layout, const std::string& where,
                                                   const Parameters* settings) const {
    const auto it = texture_layouts_.find(layout);
    if (it == texture_layouts_.end()) unknown(CapabilityKind::TextureLayout, layout, where);
    return it->second.second(settings != nullptr ? *settings : no_parameters());
}

std::shared_ptr<const TextureStorage> Registry::make_texture_storage(const std::string& layout, const Image& image,
                                                                     const std::string& where) const {
    return texture_storage_maker(layout, where)(image);
}

bool Registry::texture_layouts_use_footprint(const Parameters* settings) const {
    for (const auto& [name, layout] : texture_layouts_)
        if (layout.second(settings != nullptr ? *settings : no_parameters()).uses_footprint) return true;
    return false;
}

std::unique_ptr<Light> Registry::make_light(const std::string& type, const Parameters& parameters) const {
    const auto it = lights_.find(type);
    if (it == lights_.end()) unknown(CapabilityKind::Light, type, parameters.where("type"));
    return it->second.second(parameters);
}

std::unique_ptr<Sampler> Registry::make_sampler(const std::string& name, const std::string& where,
                                                const Parameters* options) const {
    const auto it = samplers_.find(name);
    if (it == samplers_.end()) unknown(CapabilityKind::Sampler, name, where);
    return it->second.second(options != nullptr ? *options : no_parameters());
}

std::unique_ptr<LightSampler> Registry::make_light_sampler(const std::string& name,
                                                         const std::vector<std::unique_ptr<Light>>& lights,
                                                         const std::string& where, const Parameters* options) const {
    const auto it = light_samplers_.find(name);
    if (it == light_samplers_.end()) unknown(CapabilityKind::LightSampler, name, where);
    return it->second.second(lights, options != nullptr ? *options : no_parameters());
}

std::unique_ptr<Light> Registry::make_area_light(const TriangleMesh& mesh, std::uint32_t triangle,
                                                 const Spectrum& emission) const {
    if (!area_light_) return nullptr;
    return area_light_->second(mesh, triangle, emission);
}

}  // namespace freezeray
