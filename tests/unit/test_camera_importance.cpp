// The pinhole camera's importance We and sample_wi (Veach 1997, section 10.2; pbrt-v3, 16.1.1).
#include "freezeray/camera.hpp"
#include "freezeray/ch04/camera_importance.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace freezeray;
using namespace freezeray::ch04;

namespace {

ImportancePinholeCamera make_camera(int width, int height, float fov) {
    CameraDescription d;
    d.position = Vec3(0.5f, -1.0f, 2.0f);
    d.look_at = Vec3(1.5f, 0.0f, 5.0f);
    d.up = Vec3(0, 1, 0);
    d.fov_vertical_degrees = fov;
    d.width = width;
    d.height = height;
    return ImportancePinholeCamera(d);
}

}  // namespace

TEST_CASE("the camera's importance We cos(theta) integrates to 1 over the sphere of directions, and so does "
          "pdf_direction",
          "[unit][camera][ch04]") {
    // Deterministic midpoint quadrature over (cos theta, phi) about the view direction, where
    // d(omega) = d(cos theta) d(phi): the closed form says exactly 1 (We cos dw = dA / A on the
    // image plane). The film's edges cut cells, an error below 1e-3 at this resolution.
    for (const auto& [width, height, fov] : {std::tuple{64, 48, 40.0f}, std::tuple{30, 90, 75.0f}}) {
        const ImportancePinholeCamera camera = make_camera(width, height, fov);
        const Frame frame(camera.forward());
        constexpr int bands = 3000, sectors = 6000;
        double importance = 0.0, pdf = 0.0;
        for (int i = 0; i < bands; ++i) {
            const double cos_theta = (i + 0.5) / bands;
            const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
            for (int j = 0; j < sectors; ++j) {
                const double phi = 2.0 * Pi * (j + 0.5) / sectors;
                const Vec3 local(static_cast<float>(sin_theta * std::cos(phi)), static_cast<float>(sin_theta * std::sin(phi)),
                                 static_cast<float>(cos_theta));
                const Vec3 direction = glm::normalize(frame.to_world(local));
                importance += camera.importance(Ray{camera.position(), direction}) * cos_theta;
                pdf += camera.pdf_direction(Ray{camera.position(), direction});
            }
        }
        const double cell = (1.0 / bands) * (2.0 * Pi / sectors);
        INFO(width << "x" << height << ", fov " << fov);
        CHECK(importance * cell == Approx(1.0).margin(2e-3));
        CHECK(pdf * cell == Approx(1.0).margin(2e-3));
        // At the centre of the film theta = 0: We = 1 / A.
        CHECK(camera.importance(Ray{camera.position(), camera.forward()}) == Approx(1.0f / camera.image_plane_area()));
    }
}

TEST_CASE("sample_wi finds the raster position generate_ray came from, with pdf distance^2 / cos(theta)",
          "[unit][camera][ch04]") {
    const ImportancePinholeCamera camera = make_camera(64, 48, 50.0f);
    for (int i = 0; i < 200; ++i) {
        const Vec2 film(0.3f + 63.4f * static_cast<float>((i * 37) % 200) / 200.0f,
                        0.2f + 47.6f * static_cast<float>((i * 53) % 200) / 200.0f);
        const Ray ray = camera.generate_ray(film);
        const float t = 0.5f + 0.1f * static_cast<float>(i);
        const std::optional<CameraImportanceSample> sample = camera.sample_wi(ray.at(t), Vec2(0.5f));
        REQUIRE(sample);
        CHECK(sample->raster_position.x == Approx(film.x).margin(2e-3));
        CHECK(sample->raster_position.y == Approx(film.y).margin(2e-3));
        CHECK(glm::dot(sample->wi, -ray.direction) == Approx(1.0f).margin(1e-5));
        CHECK(sample->distance == Approx(t).epsilon(1e-4));
        const float cos_theta = glm::dot(ray.direction, camera.forward());
        CHECK(sample->pdf == Approx(t * t / cos_theta).epsilon(1e-4));
        CHECK(sample->importance == Approx(camera.importance(ray)).epsilon(1e-4));
        CHECK(camera.pdf_direction(ray) == Approx(1.0f / (camera.image_plane_area() * std::pow(cos_theta, 3.0f))).epsilon(1e-4));
    }
    // Behind the camera, and in front but outside the film: nothing, and no importance.
    CHECK_FALSE(camera.sample_wi(camera.position() - camera.forward(), Vec2(0.5f)));
    const Ray outside{camera.position(), glm::normalize(camera.forward() + 3.0f * Vec3(0, 1, 0))};
    CHECK_FALSE(camera.sample_wi(outside.at(2.0f), Vec2(0.5f)));
    CHECK(camera.importance(outside) == 0.0f);
    CHECK_FALSE(camera.sample_wi(camera.position(), Vec2(0.5f)));
}
