// Alpha masks made from textures: a material's "alpha", a number in [0, 1] or "alpha_texture",
// a grey image (MTL map_d), read for every material of this chapter. Where it is below one half
// the surface is a hole (see AlphaMask in common/core/include/freezeray/material.hpp).
#pragma once

#include "freezeray/ch02/texture.hpp"
#include "freezeray/material.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/registry.hpp"

#include <memory>

namespace freezeray::ch02 {

class TextureAlphaMask final : public AlphaMask {
public:
    explicit TextureAlphaMask(FloatTexture opacity) : opacity_(std::move(opacity)) {}
    float opacity(const Vec2& uv) const override { return opacity_->eval(TextureLookup{uv}); }

private:
    FloatTexture opacity_;
};

// The alpha mask `p` describes, or null when it has none or one without holes (every value at
// least one half: the surface is whole, and rays need not look at the mask at all).
std::shared_ptr<const AlphaMask> read_alpha_mask(const Parameters& p, const MaterialContext& context);

}  // namespace freezeray::ch02
