// Vectors, colours and orthonormal frames on top of GLM.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <numbers>

namespace freezeray {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;

// Linear, scene-referred RGB radiance (or reflectance). Converted to sRGB only when a PNG is written.
using Spectrum = glm::vec3;

inline constexpr float Pi = std::numbers::pi_v<float>;
inline constexpr float InvPi = std::numbers::inv_pi_v<float>;
inline constexpr float Inv2Pi = 0.5f * std::numbers::inv_pi_v<float>;
inline constexpr float Inv4Pi = 0.25f * std::numbers::inv_pi_v<float>;
inline constexpr float OneMinusEpsilon = 0x1.fffffep-1f;  // the largest float below 1

// Relative luminance of linear Rec.709 RGB (ITU-R BT.709 weights).
inline float luminance(const Spectrum& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

inline bool is_black(const Spectrum& c) { return c.r == 0.0f && c.g == 0.0f && c.b == 0.0f; }

inline float max_component(const Vec3& v) { return glm::max(v.x, glm::max(v.y, v.z)); }

// True when every component is a finite, non-negative number: the only valid radiance.
inline bool is_valid_radiance(const Spectrum& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && c.r >= 0.0f && c.g >= 0.0f &&
           c.b >= 0.0f;
}

// An orthonormal basis (s, t, n). Local shading coordinates put the normal on +z, so that
// cos(theta) of a local direction is simply its z component.
struct Frame {
    Vec3 s, t, n;

    Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}

    // Builds a frame around a unit normal without branches or singularities:
    // Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017, listing 3.
    explicit Frame(const Vec3& normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        t = Vec3(b, sign + n.y * n.y * a, -n.y);
    }

    Vec3 to_local(const Vec3& v) const { return Vec3(glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)); }
    Vec3 to_world(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

// Direction (x, y, z) from spherical coordinates with theta measured from +z.
inline Vec3 spherical_direction(float sin_theta, float cos_theta, float phi) {
    return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

// Axis-aligned bounding box.
struct Bounds3 {
    Vec3 min{std::numeric_limits<float>::infinity()};
    Vec3 max{-std::numeric_limits<float>::infinity()};

    void expand(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void expand(const Bounds3& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool empty() const { return min.x > max.x; }
    Vec3 diagonal() const { return max - min; }
};

}  // namespace freezeray
