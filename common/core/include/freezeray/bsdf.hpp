// The BSDF interface: how a surface scatters light, in its local shading frame (normal = +z).
#pragma once

#include "freezeray/math.hpp"

#include <cstdint>
#include <optional>

namespace freezeray {

// What kinds of lobes a BSDF has. Integrators and the scene's effects set read these.
enum BSDFFlags : std::uint32_t {
    BSDF_None = 0,
    BSDF_Reflection = 1u << 0,
    BSDF_Transmission = 1u << 1,
    BSDF_Diffuse = 1u << 2,
    BSDF_Glossy = 1u << 3,
    BSDF_Specular = 1u << 4,  // a Dirac delta lobe: eval and pdf are zero, only sample() finds it
};

inline bool has_flag(std::uint32_t flags, BSDFFlags f) { return (flags & f) != 0; }

// Local-frame helpers: with the shading normal on +z, cos(theta) is the z component.
inline float cos_theta(const Vec3& w) { return w.z; }
inline float abs_cos_theta(const Vec3& w) { return std::abs(w.z); }
inline bool same_hemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0.0f; }

struct BSDFSample {
    Vec3 wi;                    // sampled incident direction, local frame, unit length
    Spectrum f{0.0f};           // BSDF value f(wo, wi) (for a delta lobe: its weight times the delta)
    float pdf = 0.0f;           // solid-angle density of wi (for a delta lobe: the lobe's probability)
    std::uint32_t flags = 0;    // the lobe that was sampled
    float eta = 1.0f;           // relative index of refraction crossed (1 for reflection)

    // The Monte Carlo weight f |cos theta_i| / pdf that multiplies the path throughput.
    Spectrum weight() const { return pdf > 0.0f ? f * abs_cos_theta(wi) / pdf : Spectrum(0.0f); }
};

// A glossy lobe's axis (shading frame, unit length) and its microfacet roughness alpha > 0.
struct GlossyLobe {
    Vec3 axis{0.0f, 0.0f, 1.0f};
    float alpha = 1.0f;
};

// Directions wo (towards the viewer) and wi (towards the light) both point away from the surface.
class BSDF {
public:
    virtual ~BSDF() = default;

    // f(wo, wi), without the cosine factor; zero for delta lobes.
    virtual Spectrum eval(const Vec3& wo, const Vec3& wi) const = 0;

    // Samples wi given wo using two uniform numbers u (and one more, u_lobe, for choosing a lobe).
    virtual std::optional<BSDFSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const = 0;

    // The solid-angle density with which sample() returns wi; zero for delta lobes.
    virtual float pdf(const Vec3& wo, const Vec3& wi) const = 0;

    // The union of the lobes' BSDFFlags.
    virtual std::uint32_t flags() const = 0;

    // Where, seen from wo, the BSDF is one glossy lobe: its axis (in the shading frame, unit
    // length) and its microfacet roughness alpha; nothing for any other BSDF. Light samplers use
    // it as a hint (chapter 10); nothing depends on it for correctness.
    virtual std::optional<GlossyLobe> glossy_lobe(const Vec3& /*wo*/) const { return std::nullopt; }
};

}  // namespace freezeray
