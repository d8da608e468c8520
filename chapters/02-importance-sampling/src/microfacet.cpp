// The Trowbridge–Reitz (GGX) distribution, its Smith masking-shadowing and the sampling of its
// visible normals (Heitz 2014 and 2018; full references in the header).
#include "freezeray/ch02/microfacet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace freezeray::ch02 {

namespace {
// The smallest alpha used in the formulas: D and Lambda divide by alpha. Below it the surface is a
// mirror anyway (effectively_smooth), and materials build the smooth BSDFs instead.
constexpr float MinimumAlpha = 1e-4f;
}  // namespace

TrowbridgeReitz::TrowbridgeReitz(float alpha_x, float alpha_y)
    : alpha_x_(std::max(alpha_x, MinimumAlpha)), alpha_y_(std::max(alpha_y, MinimumAlpha)) {}

float TrowbridgeReitz::roughness_to_alpha(float roughness) { return roughness * roughness; }

bool TrowbridgeReitz::effectively_smooth() const { return std::max(alpha_x_, alpha_y_) < 1e-3f; }

// BOOK(ggx-d)
// The anisotropic GGX distribution written without angles (Heitz 2018, section 2): for a unit wm,
//     D(wm) = 1 / (pi alpha_x alpha_y (x^2 / alpha_x^2 + y^2 / alpha_y^2 + z^2)^2),
// which equals the familiar 1 / (pi alpha^2 cos^4(theta) (1 + tan^2(theta) / alpha^2)^2) when
// alpha_x = alpha_y = alpha.
float TrowbridgeReitz::D(const Vec3& wm) const {
    if (wm.z <= 0.0f) return 0.0f;
    const float x = wm.x / alpha_x_;
    const float y = wm.y / alpha_y_;
    const float ellipse = x * x + y * y + wm.z * wm.z;
    return 1.0f / (Pi * alpha_x_ * alpha_y_ * ellipse * ellipse);
}

// Smith's Lambda for GGX (Heitz 2014, its closed form for GGX; Heitz 2018, section 2):
//     Lambda(w) = (sqrt(1 + (alpha_x^2 x^2 + alpha_y^2 y^2) / z^2) - 1) / 2.
// It grows without bound at grazing angles, where every microfacet is hidden.
float TrowbridgeReitz::lambda(const Vec3& w) const {
    const float z2 = w.z * w.z;
    if (z2 == 0.0f) return std::numeric_limits<float>::infinity();
    const float alpha2_tan2 = (alpha_x_ * alpha_x_ * w.x * w.x + alpha_y_ * alpha_y_ * w.y * w.y) / z2;
    return 0.5f * (std::sqrt(1.0f + alpha2_tan2) - 1.0f);
}

float TrowbridgeReitz::G1(const Vec3& w) const { return 1.0f / (1.0f + lambda(w)); }

// Height-correlated masking and shadowing (Heitz 2014, its height-correlated G2): a microfacet
// high up on the surface is likely to be both visible and lit, so the two are not independent.
float TrowbridgeReitz::G(const Vec3& wo, const Vec3& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }
// END BOOK

// The distribution of visible normals (Heitz 2014; Heitz 2018, section 2): microfacets
// weighted by their projected area |w.wm| as seen from w, of which the fraction G1(w) is not
// hidden; dividing by the projected area |cos theta(w)| of the macrosurface normalises it.
// Microfacets facing away from w (w.wm < 0 for w above the surface) are not visible.
float TrowbridgeReitz::D(const Vec3& w, const Vec3& wm) const {
    if (w.z == 0.0f) return 0.0f;
    const float visible_cos = w.z > 0.0f ? glm::dot(w, wm) : -glm::dot(w, wm);  // seen from w's side
    if (visible_cos <= 0.0f) return 0.0f;
    return G1(w) / std::abs(w.z) * D(wm) * visible_cos;
}

float TrowbridgeReitz::pdf(const Vec3& w, const Vec3& wm) const { return D(w, wm); }

// BOOK(ggx-visible-normals)
// Heitz 2018, the paper's listing: stretch the view direction so that the ellipsoid of normals
// becomes a hemisphere, pick a point uniformly on the hemisphere's silhouette as seen from that
// direction (a half disk below and a half ellipse above: a uniform disk squeezed onto it), lift
// the point onto the hemisphere, and stretch its normal back. Visible normals are sampled exactly,
// with density D(w, wm), whatever w.
Vec3 TrowbridgeReitz::sample_visible_normal(const Vec3& w, const Vec2& u) const {
    // EXERCISE(ch02/ggx-visible-normals): sample a microfacet normal from the distribution of the normals visible from w, book chapter 02, "Rough surfaces: GGX microfacets" (Heitz 2018)
    // Section 3.2: the view direction in the hemisphere configuration, on its upper side.
    Vec3 wh = glm::normalize(Vec3(alpha_x_ * w.x, alpha_y_ * w.y, w.z));
    if (wh.z < 0.0f) wh = -wh;

    // Section 4.1: an orthonormal basis (t1, t2, wh), with t1 horizontal.
    const float length2 = wh.x * wh.x + wh.y * wh.y;
    const Vec3 t1 = length2 > 0.0f ? Vec3(-wh.y, wh.x, 0.0f) / std::sqrt(length2) : Vec3(1.0f, 0.0f, 0.0f);
    const Vec3 t2 = glm::cross(wh, t1);

    // Section 4.2: a uniform point on the unit disk, its upper half squeezed onto the part of the
    // projected hemisphere that is visible: the disk's lower half is seen fully, the upper half
    // only down to the ellipse of the rim, whose height is wh.z times the disk's.
    const float r = std::sqrt(u.x);
    const float phi = 2.0f * Pi * u.y;
    const float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    const float s = 0.5f * (1.0f + wh.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;

    // Section 4.3: lift the point onto the hemisphere.
    const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * wh;

    // Section 3.4: back to the ellipsoid configuration (normals transform with the inverse stretch).
    return glm::normalize(Vec3(alpha_x_ * nh.x, alpha_y_ * nh.y, std::max(1e-6f, nh.z)));
    // END EXERCISE
}
// END BOOK

}  // namespace freezeray::ch02
