// Environment lights (pbrt-v3, section 14.2.4; book chapter 03).
#include "freezeray/ch03/environment_light.hpp"

#include "freezeray/ch03/directional_light.hpp"
#include "freezeray/error.hpp"
#include "freezeray/ch01/warps.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace freezeray::ch03 {

Vec2 direction_to_equirectangular(const Vec3& d) {
    float phi = std::atan2(d.x, -d.z);
    if (phi < 0.0f) phi += 2.0f * Pi;
    const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
    return Vec2(std::min(phi * Inv2Pi, OneMinusEpsilon), std::min(theta * InvPi, OneMinusEpsilon));
}

Vec3 equirectangular_to_direction(const Vec2& uv) {
    const float phi = 2.0f * Pi * uv.x, theta = Pi * uv.y;
    const float sin_theta = std::sin(theta);
    return Vec3(sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi));
}

// BOOK(environment-pdf)
float equirectangular_to_solid_angle_pdf(float pdf_uv, float sin_theta) {
    if (sin_theta <= 0.0f) return 0.0f;  // the poles: a line of the image maps to one direction
    // EXERCISE(ch03/environment-pdf): the solid-angle density of a direction drawn through the environment map's (u, v) parameterisation with density pdf_uv, book chapter 03, "Environment maps" (mind the Jacobian of the mapping)
    return pdf_uv / (2.0f * Pi * Pi * sin_theta);
    // END EXERCISE
}
// END BOOK

namespace {

// The sampling weights: each pixel's luminance times sin theta at its row's centre, because rows
// near the poles cover less of the sphere (pbrt-v3, section 14.2.4).
std::vector<float> sampling_weights(const Image& image) {
    const int width = image.width(), height = image.height();
    std::vector<float> weights(static_cast<std::size_t>(width) * height);
    for (int y = 0; y < height; ++y) {
        const float sin_theta = std::sin(Pi * (static_cast<float>(y) + 0.5f) / static_cast<float>(height));
        for (int x = 0; x < width; ++x)
            weights[static_cast<std::size_t>(y) * width + x] = luminance(image.at(x, y)) * sin_theta;
    }
    return weights;
}

}  // namespace

EnvironmentMapLight::EnvironmentMapLight(Image image, const Spectrum& scale, const Mat3& light_to_world)
    : image_(std::move(image)), scale_(scale), light_to_world_(light_to_world),
      world_to_light_(glm::transpose(light_to_world)),
      distribution_(sampling_weights(image_), static_cast<std::size_t>(image_.width()),
                    static_cast<std::size_t>(image_.height())) {}

Spectrum EnvironmentMapLight::lookup(const Vec2& uv) const {
    const int x = std::min(static_cast<int>(uv.x * static_cast<float>(image_.width())), image_.width() - 1);
    const int y = std::min(static_cast<int>(uv.y * static_cast<float>(image_.height())), image_.height() - 1);
    return scale_ * image_.at(x, y);
}

Spectrum EnvironmentMapLight::le(const Vec3& direction) const {
    return lookup(direction_to_equirectangular(world_to_light_ * direction));
}

// BOOK(environment-sample)
std::optional<LightSample> EnvironmentMapLight::sample_li(const Vec3& reference, const Vec2& u) const {
    (void)reference;  // at infinity, every point sees the same directions
    const PiecewiseConstant2D::Sample s = distribution_.sample(u.x, u.y);
    const float sin_theta = std::sin(Pi * s.v);
    const float pdf = equirectangular_to_solid_angle_pdf(s.pdf, sin_theta);
    if (pdf <= 0.0f) return std::nullopt;
    const Vec3 wi = light_to_world_ * equirectangular_to_direction(Vec2(s.u, s.v));
    // The radiance of the pixel that was sampled (not looked up again from wi, where rounding
    // could land in a neighbouring pixel that the pdf knows nothing about).
    return LightSample{lookup(Vec2(s.u, s.v)), wi, pdf, Vec3(0.0f), true};
}

float EnvironmentMapLight::pdf_li(const Vec3& reference, const Vec3& wi) const {
    (void)reference;
    const Vec3 local = world_to_light_ * wi;
    const Vec2 uv = direction_to_equirectangular(local);
    // sin theta from x and z, not sqrt(1 - y^2): within 3.5e-4 radians of a pole y rounds to +-1
    // in float, and pdf_li was 0 there although sample_li goes there (a fifth of a percent of a
    // pole row's samples; tests/chi2/test_ch03_lights.cpp caught it).
    const float sin_theta = std::sqrt(local.x * local.x + local.z * local.z);
    return equirectangular_to_solid_angle_pdf(distribution_.pdf(uv.x, uv.y), sin_theta);
}
// END BOOK

std::optional<LightEmissionSample> EnvironmentMapLight::sample_le(const Vec2& u_position, const Vec2& u_direction) const {
    const std::optional<LightSample> towards = sample_li(scene_center_, u_direction);
    if (!towards || !(scene_radius_ > 0.0f)) return std::nullopt;
    const Ray ray = ray_through_bounding_disk(-towards->wi, scene_center_, scene_radius_, u_position);
    return LightEmissionSample{ray, -towards->wi, towards->radiance, 1.0f / (Pi * scene_radius_ * scene_radius_),
                               towards->pdf};
}

EmissionDensity EnvironmentMapLight::pdf_le(const Ray& ray, const Vec3&) const {
    // Light travelling along ray.direction arrives from -ray.direction: sample_li's direction.
    return {1.0f / (Pi * scene_radius_ * scene_radius_), pdf_li(scene_center_, -ray.direction)};
}

Spectrum EnvironmentMapLight::power() const {
    // Phi = pi r^2 times the integral of L over the sphere, each pixel of row y covering exactly
    // (cos theta_y - cos theta_y+1) (2 pi / width) steradians. (It used sin theta at the row's
    // centre times pi / height, the midpoint rule, which overstates the sphere's 4 pi by the factor
    // (pi / 2h) / sin(pi / 2h): 0.6 % for 8 rows; tests/unit/test_ch03_lights.cpp compares a
    // constant map with the constant environment.)
    Spectrum integral(0.0f);
    const int width = image_.width(), height = image_.height();
    for (int y = 0; y < height; ++y) {
        const double theta0 = Pi * static_cast<double>(y) / height, theta1 = Pi * static_cast<double>(y + 1) / height;
        const auto band = static_cast<float>(std::cos(theta0) - std::cos(theta1));
        Spectrum row(0.0f);
        for (int x = 0; x < width; ++x) row += image_.at(x, y);
        integral += row * band;
    }
    integral *= 2.0f * Pi / static_cast<float>(width);
    return Pi * scene_radius_ * scene_radius_ * scale_ * integral;
}

void EnvironmentMapLight::preprocess(const Bounds3& scene_bounds) {
    bounding_sphere(scene_bounds, scene_center_, scene_radius_);
}

std::optional<LightSample> ConstantEnvironmentLight::sample_li(const Vec3& reference, const Vec2& u) const {
    (void)reference;
    return LightSample{radiance_, ch01::sample_uniform_sphere(u), ch01::uniform_sphere_pdf(), Vec3(0.0f), true};
}

float ConstantEnvironmentLight::pdf_li(const Vec3&, const Vec3&) const { return ch01::uniform_sphere_pdf(); }

std::optional<LightEmissionSample> ConstantEnvironmentLight::sample_le(const Vec2& u_position,
                                                                       const Vec2& u_direction) const {
    if (!(scene_radius_ > 0.0f)) return std::nullopt;
    const Vec3 wi = ch01::sample_uniform_sphere(u_direction);
    const Ray ray = ray_through_bounding_disk(-wi, scene_center_, scene_radius_, u_position);
    return LightEmissionSample{ray, -wi, radiance_, 1.0f / (Pi * scene_radius_ * scene_radius_), ch01::uniform_sphere_pdf()};
}

EmissionDensity ConstantEnvironmentLight::pdf_le(const Ray&, const Vec3&) const {
    return {1.0f / (Pi * scene_radius_ * scene_radius_), ch01::uniform_sphere_pdf()};
}

Spectrum ConstantEnvironmentLight::power() const {
    return Pi * scene_radius_ * scene_radius_ * 4.0f * Pi * radiance_;
}

void ConstantEnvironmentLight::preprocess(const Bounds3& scene_bounds) {
    bounding_sphere(scene_bounds, scene_center_, scene_radius_);
}

namespace {

Mat3 read_rotation(const Parameters& p) {
    if (!p.has("rotate")) return Mat3(1.0f);
    const Parameters r = p.child("rotate");
    const Vec3 axis = r.require_vec3("axis");
    if (!(glm::length(axis) > 0.0f) || !std::isfinite(glm::length(axis)))
        throw InputError(r.where("axis"), "must be a direction (not zero)");
    const float degrees = r.require_float("degrees");
    return Mat3(glm::rotate(Mat4(1.0f), glm::radians(degrees), glm::normalize(axis)));
}

Spectrum read_scale(const Parameters& p) {
    const Spectrum scale = p.get_spectrum("scale", Spectrum(1.0f));
    for (int c = 0; c < 3; ++c) p.check_range("scale", scale[c], 0.0f, 1e30f);
    return scale;
}

}  // namespace

std::unique_ptr<Light> make_environment_map_light(const Parameters& p) {
    const std::string file = p.require_existing_file("file");
    Image image = read_image(file);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(image.at(x, y)[c]) || image.at(x, y)[c] < 0.0f)
                    throw InputError(file, "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                               ") is negative or not finite; an environment map holds radiance");
    return std::make_unique<EnvironmentMapLight>(std::move(image), read_scale(p), read_rotation(p));
}

std::unique_ptr<Light> make_constant_environment_light(const Parameters& p) {
    const Spectrum radiance = p.get_spectrum("radiance", Spectrum(1.0f));
    for (int c = 0; c < 3; ++c) p.check_range("radiance", radiance[c], 0.0f, 1e30f);
    return std::make_unique<ConstantEnvironmentLight>(radiance);
}

}  // namespace freezeray::ch03
