// The course's table of contents.
#include "freezeray/course_catalogue.hpp"

namespace freezeray {

const std::vector<CatalogueEntry>& course_catalogue() {
    static const std::vector<CatalogueEntry> catalogue = {
        {CapabilityKind::Integrator, "pt-naive", 1},
        {CapabilityKind::Material, "diffuse", 1},
        {CapabilityKind::Accelerator, "bruteforce", 1},
        {CapabilityKind::Camera, "pinhole", 1},
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
        {CapabilityKind::Integrator, "bdpt-balance", 4},
        {CapabilityKind::Integrator, "light-tracing", 4},
        {CapabilityKind::Integrator, "mlt", 5},
        {CapabilityKind::Integrator, "mlt-multiplexed", 5},
        {CapabilityKind::Integrator, "auto", 5},
        {CapabilityKind::Accelerator, "kdtree", 6},
        {CapabilityKind::Integrator, "traversal-cost", 6},
        {CapabilityKind::Accelerator, "kdtree-simd", 7},
        {CapabilityKind::TextureLayout, "tiled", 8},
        {CapabilityKind::Sampler, "independent", 1},
        {CapabilityKind::Sampler, "stratified", 9},
        {CapabilityKind::Sampler, "sobol", 9},
        {CapabilityKind::Sampler, "zsobol", 9},
        {CapabilityKind::LightSampler, "power", 3},
        {CapabilityKind::LightSampler, "uniform", 3},
        {CapabilityKind::LightSampler, "bvh", 10},
        {CapabilityKind::LightSampler, "bvh-tree", 10},
    };
    return catalogue;
}

}  // namespace freezeray
