// Reading a material's alpha mask.
#include "freezeray/ch02/alpha_mask.hpp"

#include "freezeray/ch02/material_parameters.hpp"

namespace freezeray::ch02 {

std::shared_ptr<const AlphaMask> read_alpha_mask(const Parameters& p, const MaterialContext& context) {
    if (!p.has("alpha") && !p.has("alpha_texture")) return nullptr;
    FloatTexture opacity = read_float_texture(p, context, "alpha", 1.0f, 0.0f, 1.0f);
    if (opacity->minimum() >= AlphaMask::CutoutThreshold) return nullptr;
    return std::make_shared<TextureAlphaMask>(std::move(opacity));
}

}  // namespace freezeray::ch02
