// The camera's frame, and the pinhole camera.
#include "freezeray/camera.hpp"

#include <cmath>
#include <stdexcept>

namespace freezeray {

Camera::Camera(const CameraDescription& d) : position_(d.position), width_(d.width), height_(d.height) {
    forward_ = glm::normalize(d.look_at - d.position);
    // A right-handed frame: right = forward x up. Looking along +z with +y up, +x is on the
    // left of the image, as in the Cornell box's published data.
    right_ = glm::normalize(glm::cross(forward_, d.up));
    up_ = glm::cross(right_, forward_);
}

namespace {

[[noreturn]] void no_importance() {
    throw std::logic_error("this camera has no importance: the camera as a light-transport object is chapter 04's");
}

}  // namespace

float Camera::importance(const Ray&) const { no_importance(); }
float Camera::pdf_direction(const Ray&) const { no_importance(); }
std::optional<CameraImportanceSample> Camera::sample_wi(const Vec3&, const Vec2&) const { no_importance(); }

PinholeCamera::PinholeCamera(const CameraDescription& d) : Camera(d) {
    tan_half_fov_y_ = std::tan(glm::radians(d.fov_vertical_degrees) * 0.5f);
    aspect_ = static_cast<float>(d.width) / static_cast<float>(d.height);
}

// BOOK(generate-camera-ray)
Ray PinholeCamera::generate_ray(const Vec2& film_position) const {
    // Film position to normalised device coordinates in [-1, 1], +y up; then onto the image
    // plane at distance 1, whose half-height is tan(fov_y / 2).
    const float ndc_x = 2.0f * film_position.x / static_cast<float>(width_) - 1.0f;
    const float ndc_y = 1.0f - 2.0f * film_position.y / static_cast<float>(height_);
    const Vec3 direction =
        forward_ + (ndc_x * aspect_ * tan_half_fov_y_) * right_ + (ndc_y * tan_half_fov_y_) * up_;
    return Ray{position_, glm::normalize(direction)};
}
// END BOOK

float PinholeCamera::image_plane_area() const {
    const float half_height = tan_half_fov_y_;
    const float half_width = aspect_ * tan_half_fov_y_;
    return 4.0f * half_width * half_height;
}

std::optional<Vec2> PinholeCamera::raster_position(const Vec3& direction) const {
    const float cos_theta = glm::dot(direction, forward_);
    if (!(cos_theta > 0.0f)) return std::nullopt;
    // The point where the direction crosses the image plane at distance 1, in the camera's
    // right/up coordinates, then generate_ray's mapping backwards.
    const Vec3 on_plane = direction / cos_theta;
    const float ndc_x = glm::dot(on_plane, right_) / (aspect_ * tan_half_fov_y_);
    const float ndc_y = glm::dot(on_plane, up_) / tan_half_fov_y_;
    const Vec2 film((ndc_x + 1.0f) * 0.5f * static_cast<float>(width_), (1.0f - ndc_y) * 0.5f * static_cast<float>(height_));
    if (!(film.x >= 0.0f && film.x < static_cast<float>(width_) && film.y >= 0.0f && film.y < static_cast<float>(height_)))
        return std::nullopt;
    return film;
}

}  // namespace freezeray
