// Plastic: a diffuse base under a smooth or rough dielectric coating.
#include "freezeray/ch02/materials.hpp"
#include "freezeray/ch02/plastic.hpp"

namespace freezeray::ch02 {

const BSDF* PlasticMaterial::bsdf(const Hit& hit, ScratchArena& arena) const {
    const Spectrum albedo = albedo_->eval(hit.texture_lookup());
    const TrowbridgeReitz distribution = roughness_.distribution(hit.texture_lookup());
    // The BSDF keeps a pointer to its coating's distribution, so that lives in the arena too.
    const TrowbridgeReitz* coating =
        distribution.effectively_smooth() ? nullptr : arena.make<TrowbridgeReitz>(distribution);
    return arena.make<PlasticBSDF>(albedo, eta_, coating);
}

// "albedo" (or "albedo_texture") of the base, "ior" of the coating (default 1.5), and for the
// rough variant the roughness of the coating.
std::unique_ptr<Material> make_plastic_material(const Parameters& p, const MaterialContext& context, bool rough) {
    SpectrumTexture albedo = read_spectrum_texture(p, context, "albedo", Spectrum(0.5f), 0.0f, 1.0f);
    const float eta = read_index_of_refraction(p, 1.5f);
    return std::make_unique<PlasticMaterial>(std::move(albedo), eta,
                                             rough ? read_microfacet_roughness(p, context, DefaultRoughness) : smooth_roughness());
}

}  // namespace freezeray::ch02
