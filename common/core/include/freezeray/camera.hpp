// The pinhole camera: a look-at frame, a vertical field of view, any aspect ratio.
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/ray.hpp"

#include <optional>

namespace freezeray {

struct CameraDescription {
    Vec3 position{0.0f};
    Vec3 look_at{0.0f, 0.0f, 1.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float fov_vertical_degrees = 40.0f;
    int width = 256;
    int height = 256;
};

class PinholeCamera {
public:
    explicit PinholeCamera(const CameraDescription& description);

    // The primary ray through film position (x, y) in pixels, (0, 0) the top-left corner of the
    // image and (width, height) the bottom-right: pixel (i, j) covers [i, i+1) x [j, j+1).
    Ray generate_ray(const Vec2& film_position) const;

    // Where a direction leaving the pinhole crosses the film, in pixels (the inverse of
    // generate_ray); nothing when it points behind the camera or outside the film.
    std::optional<Vec2> raster_position(const Vec3& direction) const;
    // A: the area of the image rectangle at distance 1 from the pinhole (chapter 04's camera
    // importance is 1 / (A cos^4 theta)).
    float image_plane_area() const;
    // The side of one pixel on the image plane at distance 1, at the image's centre: the angle
    // (in radians, for small angles) one pixel spans there.
    float pixel_spread() const { return 2.0f * tan_half_fov_y_ / static_cast<float>(height_); }

    int width() const { return width_; }
    int height() const { return height_; }
    const Vec3& position() const { return position_; }
    const Vec3& forward() const { return forward_; }
    const Vec3& right() const { return right_; }

private:
    Vec3 position_, forward_, right_, up_;
    float tan_half_fov_y_, aspect_;
    int width_, height_;
};

}  // namespace freezeray
