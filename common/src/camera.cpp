// The pinhole camera.
#include "freezeray/camera.hpp"

#include <cmath>

namespace freezeray {

PinholeCamera::PinholeCamera(const CameraDescription& d)
    : position_(d.position), width_(d.width), height_(d.height) {
    forward_ = glm::normalize(d.look_at - d.position);
    // A right-handed frame: right = forward x up. Looking along +z with +y up, +x is on the
    // left of the image, as in the Cornell box's published data.
    right_ = glm::normalize(glm::cross(forward_, d.up));
    up_ = glm::cross(right_, forward_);
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

}  // namespace freezeray
