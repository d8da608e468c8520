// The pinhole camera as a light-transport object: its importance We, the density of its rays'
// directions, and the importance arriving at a point from the pinhole, which light tracing and
// bidirectional path tracing connect to (Veach 1997, section 10.2; pbrt-v3, section 16.1).
#pragma once

#include "freezeray/camera.hpp"
#include "freezeray/math.hpp"
#include "freezeray/ray.hpp"

#include <optional>

namespace freezeray::ch04 {

// A direction towards the camera sampled from a point in the scene (sample_camera_wi), for
// light tracing: the path's vertex is connected to the pinhole and splatted at raster_position
// (Veach 1997, section 10.2; pbrt-v3, section 16.1.2).
struct CameraImportanceSample {
    Vec3 wi;                // unit direction from the reference point towards the pinhole
    float importance = 0;   // We(pinhole -> reference point), see camera_importance
    // Density of choosing the pinhole, in solid angle at the reference point: distance^2 /
    // cos(theta) at the camera. The pinhole is a delta position, so this is the "pdf" that
    // turns We into the importance arriving at the reference point (pbrt-v3, section 16.1.2).
    float pdf = 0;
    Vec2 raster_position;   // film position (pixels) where the ray from the pinhole crosses the film
    float distance = 0;     // from the reference point to the pinhole
};

// BOOK(camera-importance-interface)
// The camera's importance We(ray) for a ray leaving the pinhole (Veach 1997, section 10.2;
// pbrt-v3, section 16.1.1): 1 / (A cos^4 theta) for rays through the film, 0 otherwise, with
// theta the angle to the view direction and A the area of the image rectangle at distance 1.
// Normalisation: the integral of We cos(theta) over the film's solid angle is 1, so that a
// pixel's share of it (1 / pixel count) is the box filter of generate_ray: a pixel's value
// is the mean radiance over the rays through it.
float camera_importance(const PinholeCamera& camera, const Ray& ray);
// The densities with which a camera ray leaving along `direction` is generated, as pbrt's
// Pdf_We: the position is a delta (1); the direction has solid-angle density
// 1 / (A cos^3 theta) over the film (uniform on the image plane), 0 outside it.
float camera_pdf_direction(const PinholeCamera& camera, const Vec3& direction);
// The importance arriving at `reference` from the pinhole (see CameraImportanceSample);
// nothing when the point is behind the camera or projects outside the film. The pinhole
// has no area, so no random number is used.
std::optional<CameraImportanceSample> sample_camera_wi(const PinholeCamera& camera, const Vec3& reference);
// END BOOK

}  // namespace freezeray::ch04
