// The pinhole camera's importance (book chapter 04).
#include "freezeray/ch04/camera_importance.hpp"

#include <cmath>

namespace freezeray::ch04 {

// BOOK(camera-importance)
float camera_importance(const PinholeCamera& camera, const Ray& ray) {
    if (!camera.raster_position(ray.direction)) return 0.0f;
    // Over the film, dA on the image plane at distance 1 is seen under the solid angle
    // cos^3(theta) dA, so We cos(theta) dw = dA / A: integrating over the film gives 1.
    const float cos_theta = glm::dot(ray.direction, camera.forward());
    const float cos2 = cos_theta * cos_theta;
    return 1.0f / (camera.image_plane_area() * cos2 * cos2);
}

float camera_pdf_direction(const PinholeCamera& camera, const Vec3& direction) {
    if (!camera.raster_position(direction)) return 0.0f;
    const float cos_theta = glm::dot(direction, camera.forward());
    return 1.0f / (camera.image_plane_area() * cos_theta * cos_theta * cos_theta);
}

std::optional<CameraImportanceSample> sample_camera_wi(const PinholeCamera& camera, const Vec3& reference) {
    const Vec3 to_camera = camera.position() - reference;
    const float distance = glm::length(to_camera);
    if (!(distance > 0.0f)) return std::nullopt;
    const Vec3 wi = to_camera / distance;
    const std::optional<Vec2> raster = camera.raster_position(-wi);
    if (!raster) return std::nullopt;
    const float cos_theta = glm::dot(-wi, camera.forward());
    CameraImportanceSample sample;
    sample.wi = wi;
    sample.importance = camera_importance(camera, Ray{camera.position(), -wi});
    // The pinhole's delta position, converted from "area" (a point: density 1) to solid angle at
    // the reference point: distance^2 / cos(theta_camera) (pbrt-v3's PerspectiveCamera::Sample_Wi
    // with a lens of area 1).
    sample.pdf = distance * distance / cos_theta;
    sample.raster_position = *raster;
    sample.distance = distance;
    return sample;
}
// END BOOK

}  // namespace freezeray::ch04
