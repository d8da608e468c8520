// Area lights sampled uniformly by area, their density converted to solid angle (book chapter 03).
#include "freezeray/ch03/area_light.hpp"

#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/triangle_intersection.hpp"
#include "freezeray/ch01/warps.hpp"

#include <cmath>

namespace freezeray::ch03 {

// BOOK(area-to-solid-angle)
float area_to_solid_angle_pdf(float pdf_area, float distance_squared, float cos_light) {
    // EXERCISE(ch03/area-to-solid-angle): convert a density per unit area on the light into a density per unit solid angle at the shading point, book chapter 03, "Sampling the light instead of the BSDF"
    return pdf_area * distance_squared / cos_light;
    // END EXERCISE
}
// END BOOK

TriangleLight::TriangleLight(const TriangleMesh& mesh, std::uint32_t triangle, const Spectrum& emission)
    : emission_(emission) {
    const auto& idx = mesh.triangles[triangle];
    p0_ = mesh.positions[idx[0]];
    p1_ = mesh.positions[idx[1]];
    p2_ = mesh.positions[idx[2]];
    const Vec3 cross = glm::cross(p1_ - p0_, p2_ - p0_);
    // As in make_hit: scaled before normalising so that tiny triangles keep a normal.
    normal_ = glm::normalize(cross / max_component(glm::abs(cross)));
    area_ = mesh.triangle_area(triangle);
}

// BOOK(area-light-sample)
std::optional<LightSample> TriangleLight::sample_li(const Vec3& reference, const Vec2& u) const {
    const Vec2 b = ch01::sample_uniform_triangle(u);
    const Vec3 point = (1.0f - b.x - b.y) * p0_ + b.x * p1_ + b.y * p2_;
    const Vec3 to_light = point - reference;
    const float distance_squared = glm::dot(to_light, to_light);
    if (!(distance_squared > 0.0f)) return std::nullopt;
    const Vec3 wi = to_light / std::sqrt(distance_squared);
    const float cos_light = -glm::dot(normal_, wi);
    if (cos_light <= 0.0f) return std::nullopt;  // the reference point is behind the emitter
    const float pdf = area_to_solid_angle_pdf(1.0f / area_, distance_squared, cos_light);
    if (!std::isfinite(pdf)) return std::nullopt;  // grazing: a direction of zero solid angle
    return LightSample{emission_, wi, pdf, point, false, normal_};
}
// END BOOK

float TriangleLight::pdf_li(const Vec3& reference, const Vec3& wi) const {
    // The density of the direction is that of the point it meets on the triangle.
    const Ray ray{reference, wi};
    const std::optional<TriangleHit> hit = intersect_triangle(ray, RayShear(wi), p0_, p1_, p2_);
    if (!hit) return 0.0f;
    const float cos_light = -glm::dot(normal_, wi);
    if (cos_light <= 0.0f) return 0.0f;
    const float pdf = area_to_solid_angle_pdf(1.0f / area_, hit->t * hit->t, cos_light);
    return std::isfinite(pdf) ? pdf : 0.0f;
}

std::optional<LightEmissionSample> TriangleLight::sample_le(const Vec2& u_position, const Vec2& u_direction) const {
    const Vec2 b = ch01::sample_uniform_triangle(u_position);
    const Vec3 point = (1.0f - b.x - b.y) * p0_ + b.x * p1_ + b.y * p2_;
    // Cosine-weighted directions about the front normal: the distribution of a Lambertian emitter.
    const Vec3 local = ch02::sample_cosine_hemisphere(u_direction);
    const float pdf_direction = ch02::cosine_hemisphere_pdf(local.z);
    if (pdf_direction <= 0.0f) return std::nullopt;
    const Vec3 direction = Frame(normal_).to_world(local);
    return LightEmissionSample{Ray{point, direction}, normal_, emission_, 1.0f / area_, pdf_direction};
}

EmissionDensity TriangleLight::pdf_le(const Ray& ray, const Vec3& normal) const {
    (void)normal;  // the triangle's own
    const float cos_light = glm::dot(normal_, ray.direction);
    return {1.0f / area_, ch02::cosine_hemisphere_pdf(cos_light)};
}

// A Lambertian emitter of radiance Le and area A sends Phi = pi A Le (one side).
Spectrum TriangleLight::power() const { return Pi * area_ * emission_; }

}  // namespace freezeray::ch03
