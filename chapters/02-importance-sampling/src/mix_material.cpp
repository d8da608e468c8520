// The mix material: two materials blended by a (possibly textured) weight.
#include "freezeray/ch02/materials.hpp"
#include "freezeray/ch02/mix_bsdf.hpp"
#include "freezeray/error.hpp"

namespace freezeray::ch02 {

// BOOK(mix-material-bsdf)
const BSDF* MixMaterial::bsdf(const Hit& hit, ScratchArena& arena) const {
    // Both parts are built at the same point, in the same arena, and blended by the weight there.
    return arena.make<MixBSDF>(first_->bsdf(hit, arena), second_->bsdf(hit, arena), weight_->eval(hit.texture_lookup()));
}
// END BOOK

namespace {

// One part of the mix, described inline by the object at `key`.
std::shared_ptr<const Material> read_part(const Parameters& p, const MaterialContext& context, const std::string& key,
                                          const MaterialBuilder& build_part) {
    const Parameters part = p.child(key);
    std::shared_ptr<const Material> material = build_part(part, context);
    // A part has no name of its own and emits nothing: every key of its object must be one it read.
    refuse_unknown_keys(part);
    return material;
}

}  // namespace

// "first" and "second": the two materials, as objects with a "type"; "weight" (or
// "weight_texture"): the fraction of `second`, in [0, 1], default 0.5.
std::unique_ptr<Material> make_mix_material(const Parameters& p, const MaterialContext& context, const MaterialBuilder& build_part) {
    if (p.has("materials"))
        throw InputError(p.where("materials"), "naming other materials of the scene is not supported yet; describe the "
                                               "two parts inline as \"first\": {...} and \"second\": {...}");
    std::shared_ptr<const Material> first = read_part(p, context, "first", build_part);
    std::shared_ptr<const Material> second = read_part(p, context, "second", build_part);
    FloatTexture weight = read_float_texture(p, context, "weight", 0.5f, 0.0f, 1.0f);
    return std::make_unique<MixMaterial>(std::move(first), std::move(second), std::move(weight));
}

}  // namespace freezeray::ch02
