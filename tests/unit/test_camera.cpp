// The pinhole camera's rays.
#include "freezeray/camera.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;

TEST_CASE("the centre of the film looks along the view direction, the edges at half the fov", "[unit][camera]") {
    CameraDescription d;
    d.position = Vec3(1, 2, 3);
    d.look_at = Vec3(1, 2, 10);
    d.up = Vec3(0, 1, 0);
    d.fov_vertical_degrees = 60.0f;
    d.width = 200;
    d.height = 100;
    const PinholeCamera camera(d);

    const Ray centre = camera.generate_ray(Vec2(100, 50));
    CHECK(centre.origin == d.position);
    CHECK(centre.direction.z == Approx(1.0f));

    // Top edge: 30 degrees above the axis, and up is +y.
    const Ray top = camera.generate_ray(Vec2(100, 0));
    CHECK(glm::degrees(std::acos(top.direction.z)) == Approx(30.0f).epsilon(1e-4));
    CHECK(top.direction.y > 0.0f);

    // Aspect 2: the right edge is at atan(2 tan 30 deg); looking along +z with +y up, the
    // right of the image is -x (right-handed frame).
    const Ray right = camera.generate_ray(Vec2(200, 50));
    CHECK(std::atan2(-right.direction.x, right.direction.z) == Approx(std::atan(2.0f * std::tan(glm::radians(30.0f)))));
    CHECK(glm::length(right.direction) == Approx(1.0f));
}
