// Glass: smooth and rough dielectric interfaces.
#include "freezeray/ch02/materials.hpp"
#include "freezeray/ch02/rough_dielectric.hpp"
#include "freezeray/ch02/smooth_dielectric.hpp"

namespace freezeray::ch02 {

const BSDF* DielectricMaterial::bsdf(const Hit& hit, ScratchArena& arena) const {
    const TrowbridgeReitz distribution = roughness_.distribution(hit.texture_lookup());
    if (distribution.effectively_smooth()) return arena.make<SmoothDielectricBSDF>(eta_);
    return arena.make<RoughDielectricBSDF>(distribution, eta_);
}

// "ior" (default 1.5, window glass; MTL Ni), and for the rough variant the roughness.
std::unique_ptr<Material> make_dielectric_material(const Parameters& p, const MaterialContext& context, bool rough) {
    const float eta = read_index_of_refraction(p, 1.5f);
    return std::make_unique<DielectricMaterial>(eta, rough ? read_microfacet_roughness(p, context, DefaultRoughness)
                                                           : smooth_roughness());
}

}  // namespace freezeray::ch02
