// The camera: what a render asks of it (rays through the film; for the light-transport chapters
// its importance), and its first kind, the pinhole. Cameras are a registered kind (the registry's
// `cameras`, chosen by the scene's "camera"/"type"); a lens is a new member (chapter 16).
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/ray.hpp"

#include <optional>

namespace freezeray {

// What every camera of a scene file states: where it is, where it looks, its vertical field of
// view and the image's size. A kind of camera reads its own keys from the "camera" block besides.
struct CameraDescription {
    Vec3 position{0.0f};
    Vec3 look_at{0.0f, 0.0f, 1.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float fov_vertical_degrees = 40.0f;
    int width = 256;
    int height = 256;
};

// A point on the camera that a point in the scene connects to, for light tracing and the
// bidirectional strategies that splat (Veach 1997, section 10.2; pbrt-v3, section 16.1.2).
struct CameraImportanceSample {
    Vec3 position;          // the point on the camera (the pinhole; a point on a lens)
    Vec3 wi;                // unit direction from the reference point towards it
    float importance = 0;   // We of the ray from `position` through the reference point
    // Density of choosing `position`, in solid angle at the reference point: for the pinhole, a
    // delta position, distance^2 / cos(theta) at the camera (pbrt-v3, section 16.1.2).
    float pdf = 0;
    Vec2 raster_position;   // film position (pixels) the ray from the camera crosses
    float distance = 0;     // from the reference point to `position`
};

class Camera {
public:
    explicit Camera(const CameraDescription& description);
    virtual ~Camera() = default;

    // The primary ray through film position (x, y) in pixels, (0, 0) the top-left corner of the
    // image and (width, height) the bottom-right: pixel (i, j) covers [i, i+1) x [j, j+1).
    virtual Ray generate_ray(const Vec2& film_position) const = 0;

    // The camera as a light-transport object (book chapter 04): its importance We for a ray
    // leaving it, the density of such a ray's direction (pbrt's Pdf_We; the position's density
    // is the camera's own), and the importance arriving at `reference` from a point of the
    // camera chosen with `u` (nothing when the point is behind it or projects outside the film).
    // Chapter 04 teaches them and registers a pinhole that has them; before it, no integrator
    // asks, and a camera without them says so (std::logic_error).
    virtual float importance(const Ray& ray) const;
    virtual float pdf_direction(const Ray& ray) const;
    virtual std::optional<CameraImportanceSample> sample_wi(const Vec3& reference, const Vec2& u) const;

    // The angle (in radians, for small angles) one pixel spans at the image's centre: how wide a
    // pixel's footprint is (chapter 08's ray differentials).
    virtual float pixel_spread() const = 0;

    int width() const { return width_; }
    int height() const { return height_; }
    // The camera's frame: its centre (the pinhole, the lens's centre), the view direction and
    // the image's right.
    const Vec3& position() const { return position_; }
    const Vec3& forward() const { return forward_; }
    const Vec3& right() const { return right_; }
    const Vec3& up() const { return up_; }

protected:
    Vec3 position_, forward_, right_, up_;
    int width_, height_;
};

// The pinhole camera: a look-at frame, a vertical field of view, any aspect ratio. The
// registry's constructor registers it as camera "pinhole"; chapter 04 replaces it with one that
// has importance (ch04::ImportancePinholeCamera).
class PinholeCamera : public Camera {
public:
    explicit PinholeCamera(const CameraDescription& description);

    Ray generate_ray(const Vec2& film_position) const override;
    float pixel_spread() const override { return 2.0f * tan_half_fov_y_ / static_cast<float>(height_); }

    // Where a direction leaving the pinhole crosses the film, in pixels (the inverse of
    // generate_ray); nothing when it points behind the camera or outside the film.
    std::optional<Vec2> raster_position(const Vec3& direction) const;
    // A: the area of the image rectangle at distance 1 from the pinhole (chapter 04's camera
    // importance is 1 / (A cos^4 theta)).
    float image_plane_area() const;

private:
    float tan_half_fov_y_, aspect_;
};

}  // namespace freezeray
