// Materials: what a surface is made of. At a hit, a material builds the BSDF for that point
// (its parameters may vary over the surface) and says what light the surface emits.
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/hit.hpp"
#include "freezeray/math.hpp"
#include "freezeray/scratch_arena.hpp"

#include <cstdint>
#include <memory>
#include <string>

namespace freezeray {

// An alpha mask: where its opacity is below one half, the surface is not there and rays pass
// through it (a cut-out: leaves, chains, fences drawn on a few quads). Scene::intersect and
// Scene::occluded honour it; chapter 02 makes masks from image textures (a material's "alpha").
class AlphaMask {
public:
    virtual ~AlphaMask() = default;
    // The opacity at texture coordinates uv, in [0, 1].
    virtual float opacity(const Vec2& uv) const = 0;
    // Opacities below this are holes. A threshold, not a blend: the surface is either there or not,
    // so the estimator stays the same (pbrt-v3 tests alpha masks the same way, against 0).
    static constexpr float CutoutThreshold = 0.5f;
};

class Material {
public:
    virtual ~Material() = default;

    // The BSDF at `hit`, allocated in `arena` (valid until the arena is reset).
    virtual const BSDF* bsdf(const Hit& hit, ScratchArena& arena) const = 0;

    // The union of the BSDF flags this material can produce anywhere on its surface.
    virtual std::uint32_t flags() const = 0;

    // True when any parameter comes from a texture.
    virtual bool is_textured() const { return false; }

    // Emitted radiance Le leaving the front side (emitters are one-sided, as in Mitsuba).
    Spectrum emission{0.0f};
    bool is_emissive() const { return !is_black(emission); }

    // Null for an opaque material (the usual case).
    std::shared_ptr<const AlphaMask> alpha_mask;
    // True when `hit` falls in a hole of the alpha mask.
    bool is_cut_out(const Hit& hit) const {
        return alpha_mask != nullptr && alpha_mask->opacity(hit.uv) < AlphaMask::CutoutThreshold;
    }
    std::string name;  // the MTL or JSON name
    std::string type;  // the registry name it was made with ("diffuse", ...)
};

// The local shading frame of a BSDF at `hit`, seen from direction `wo` (world space, pointing
// away from the surface). Surfaces that only reflect are two-sided: seen from behind, the frame
// is turned to face `wo`. Transmissive ones keep their true side (inside and outside differ).
inline Frame shading_frame(const Hit& hit, const BSDF& bsdf, const Vec3& wo) {
    Vec3 normal = hit.shading_normal;
    if (!has_flag(bsdf.flags(), BSDF_Transmission) && glm::dot(normal, wo) < 0.0f) normal = -normal;
    return Frame(normal);
}

// Le(x, wo) of a surface: `emission` on the front side, black behind it.
inline Spectrum emitted_radiance(const Material& m, const Hit& hit, const Vec3& wo) {
    return glm::dot(hit.geometric_normal, wo) > 0.0f ? m.emission : Spectrum(0.0f);
}

}  // namespace freezeray
