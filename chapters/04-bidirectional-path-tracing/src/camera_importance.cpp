// The pinhole camera's importance (book chapter 04).
#include "freezeray/ch04/camera_importance.hpp"

#include <cmath>

namespace freezeray::ch04 {

// BOOK(camera-importance)
float ImportancePinholeCamera::importance(const Ray& ray) const {
    if (!raster_position(ray.direction)) return 0.0f;
    // Over the film, dA on the image plane at distance 1 is seen under the solid angle
    // cos^3(theta) dA, so We cos(theta) dw = dA / A: integrating over the film gives 1.
    const float cos_theta = glm::dot(ray.direction, forward());
    const float cos2 = cos_theta * cos_theta;
    return 1.0f / (image_plane_area() * cos2 * cos2);
}

float ImportancePinholeCamera::pdf_direction(const Ray& ray) const {
    if (!raster_position(ray.direction)) return 0.0f;
    const float cos_theta = glm::dot(ray.direction, forward());
    return 1.0f / (image_plane_area() * cos_theta * cos_theta * cos_theta);
}

std::optional<CameraImportanceSample> ImportancePinholeCamera::sample_wi(const Vec3& reference, const Vec2&) const {
    const Vec3 to_camera = position() - reference;
    const float distance = glm::length(to_camera);
    if (!(distance > 0.0f)) return std::nullopt;
    const Vec3 wi = to_camera / distance;
    const std::optional<Vec2> raster = raster_position(-wi);
    if (!raster) return std::nullopt;
    const float cos_theta = glm::dot(-wi, forward());
    CameraImportanceSample sample;
    sample.position = position();
    sample.wi = wi;
    sample.importance = importance(Ray{position(), -wi});
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
