// The diffuse material: a textured albedo over the cosine-sampled Lambertian BSDF.
#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/ch02/materials.hpp"

namespace freezeray::ch02 {

// BOOK(diffuse-material-bsdf)
const BSDF* DiffuseMaterial::bsdf(const Hit& hit, ScratchArena& arena) const {
    return arena.make<CosineLambertianBSDF>(albedo_->eval(hit.texture_lookup()));
}
// END BOOK

std::unique_ptr<Material> make_diffuse_material(const Parameters& p, const MaterialContext& context) {
    return std::make_unique<DiffuseMaterial>(read_spectrum_texture(p, context, "albedo", Spectrum(0.5f), 0.0f, 1.0f));
}

}  // namespace freezeray::ch02
