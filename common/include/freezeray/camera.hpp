// The pinhole camera: a look-at frame, a vertical field of view, any aspect ratio.
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/ray.hpp"

#include <optional>

namespace freezeray {

// A direction towards the camera sampled from a point in the scene (PinholeCamera::sample_wi),
// for light tracing: the path's vertex is connected to the pinhole and splatted at
// raster_position (Veach 1997, section 10.2; pbrt-v3, section 16.1.2).
struct CameraImportanceSample {
    Vec3 wi;                // unit direction from the reference point towards the pinhole
    float importance = 0;   // We(pinhole -> reference point), see PinholeCamera::importance
    // Density of choosing the pinhole, in solid angle at the reference point: distance^2 /
    // cos(theta) at the camera. The pinhole is a delta position, so this is the "pdf" that
    // turns We into the importance arriving at the reference point (pbrt-v3, section 16.1.2).
    float pdf = 0;
    Vec2 raster_position;   // film position (pixels) where the ray from the pinhole crosses the film
    float distance = 0;     // from the reference point to the pinhole
};

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

    // BOOK(camera-importance-interface)
    // The camera's importance We(ray) for a ray leaving the pinhole (Veach 1997, section 10.2;
    // pbrt-v3, section 16.1.1): 1 / (A cos^4 theta) for rays through the film, 0 otherwise, with
    // theta the angle to the view direction and A the area of the image rectangle at distance 1.
    // Normalisation: the integral of We cos(theta) over the film's solid angle is 1, so that a
    // pixel's share of it (1 / pixel count) is the box filter of generate_ray: a pixel's value
    // is the mean radiance over the rays through it.
    float importance(const Ray& ray) const;
    // The densities with which a camera ray leaving along ray.direction is generated, as pbrt's
    // Pdf_We: the position is a delta (1); the direction has solid-angle density
    // 1 / (A cos^3 theta) over the film (uniform on the image plane), 0 outside it.
    float pdf_direction(const Vec3& direction) const;
    // The importance arriving at `reference` from the pinhole (see CameraImportanceSample);
    // nothing when the point is behind the camera or projects outside the film. The pinhole
    // has no area, so no random number is used.
    std::optional<CameraImportanceSample> sample_wi(const Vec3& reference) const;
    // Where a direction leaving the pinhole crosses the film, in pixels (the inverse of
    // generate_ray); nothing when it points behind the camera or outside the film.
    std::optional<Vec2> raster_position(const Vec3& direction) const;
    // A: the area of the image rectangle at distance 1 from the pinhole.
    float image_plane_area() const;
    // END BOOK

    int width() const { return width_; }
    int height() const { return height_; }
    const Vec3& position() const { return position_; }
    const Vec3& forward() const { return forward_; }

private:
    Vec3 position_, forward_, right_, up_;
    float tan_half_fov_y_, aspect_;
    int width_, height_;
};

}  // namespace freezeray
