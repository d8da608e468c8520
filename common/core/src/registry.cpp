// The registry of capabilities by name.
#include "freezeray/registry.hpp"

#include <algorithm>
#include <stdexcept>

namespace freezeray {

namespace {

std::shared_ptr<RendererIdentity> make_identity(std::string program, int chapter) {
    auto renderer = std::make_shared<RendererIdentity>();
    renderer->program = std::move(program);
    renderer->chapter = chapter;
    return renderer;
}

}  // namespace

Registry::Registry(std::string program, int chapter)
    : renderer_(make_identity(std::move(program), chapter)),
      integrators(CapabilityKind::Integrator, renderer_),
      materials(CapabilityKind::Material, renderer_),
      accelerators(CapabilityKind::Accelerator, renderer_),
      lights(CapabilityKind::Light, renderer_),
      texture_layouts(CapabilityKind::TextureLayout, renderer_),
      samplers(CapabilityKind::Sampler, renderer_),
      light_samplers(CapabilityKind::LightSampler, renderer_),
      cameras(CapabilityKind::Camera, renderer_) {
    accelerators.add("bruteforce", 1, "every triangle of every mesh whose bounding box the ray meets",
                     [](const Parameters&) { return std::make_unique<BruteForceAccelerator>(); });
    samplers.add("independent", 1, "independent uniform numbers, one PCG32 stream per pixel sample",
                 [](const Parameters&) { return std::make_unique<IndependentSampler>(); });
    cameras.add("pinhole", 1, "a pinhole: position, look_at, up, fov_vertical_degrees, resolution",
                [](const CameraDescription& description, const Parameters&) {
                    return std::make_unique<PinholeCamera>(description);
                });
}

const CatalogueBase& Registry::catalogue(CapabilityKind kind) const {
    switch (kind) {
        case CapabilityKind::Integrator: return integrators;
        case CapabilityKind::Material: return materials;
        case CapabilityKind::Accelerator: return accelerators;
        case CapabilityKind::Light: return lights;
        case CapabilityKind::TextureLayout: return texture_layouts;
        case CapabilityKind::Sampler: return samplers;
        case CapabilityKind::LightSampler: return light_samplers;
        case CapabilityKind::Camera: return cameras;
    }
    throw std::logic_error("a capability kind without a catalogue");
}

void Registry::add_area_light(int chapter, const std::string& summary, AreaLightFactory factory) {
    // Listed among the lights; made only here, for emissive triangles (the loader refuses "area"
    // in the "lights" array).
    lights.add("area", chapter, summary, LightFactory{});
    area_light_ = std::move(factory);
}

std::unique_ptr<Light> Registry::make_area_light(const TriangleMesh& mesh, std::uint32_t triangle,
                                                 const Spectrum& emission) const {
    if (!area_light_) return nullptr;
    return area_light_(mesh, triangle, emission);
}

TextureStorageMaker Registry::texture_storage_maker(const std::string& layout, const std::string& where,
                                                   const Parameters* settings) const {
    return texture_layouts.make(layout, where, settings != nullptr ? *settings : Parameters::none());
}

TextureFootprint Registry::texture_footprint(const Parameters* settings) const {
    for (const Entry& layout : texture_layouts.list())
        if (const TextureFootprint footprint = texture_storage_maker(layout.name, layout.name, settings).footprint)
            return footprint;
    return nullptr;
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

void Registry::set_catalogue(const std::vector<CatalogueEntry>& table_of_contents) {
    renderer_->table_of_contents = &table_of_contents;
}

}  // namespace freezeray
