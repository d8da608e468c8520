// The pinhole camera as a light-transport object: its importance We, the density of its rays'
// directions, and the importance arriving at a point from the pinhole, which light tracing and
// bidirectional path tracing connect to (Veach 1997, section 10.2; pbrt-v3, section 16.1).
// Chapter 04 registers it as camera "pinhole", in place of common/'s pinhole without importance.
#pragma once

#include "freezeray/camera.hpp"
#include "freezeray/math.hpp"
#include "freezeray/ray.hpp"

#include <optional>

namespace freezeray::ch04 {

// BOOK(camera-importance-interface)
class ImportancePinholeCamera final : public PinholeCamera {
public:
    using PinholeCamera::PinholeCamera;

    // The camera's importance We(ray) for a ray leaving the pinhole (Veach 1997, section 10.2;
    // pbrt-v3, section 16.1.1): 1 / (A cos^4 theta) for rays through the film, 0 otherwise, with
    // theta the angle to the view direction and A the area of the image rectangle at distance 1.
    // Normalisation: the integral of We cos(theta) over the film's solid angle is 1, so that a
    // pixel's share of it (1 / pixel count) is the box filter of generate_ray: a pixel's value
    // is the mean radiance over the rays through it.
    float importance(const Ray& ray) const override;
    // The densities with which a camera ray leaving along `ray.direction` is generated, as
    // pbrt's Pdf_We: the position is a delta (1); the direction has solid-angle density
    // 1 / (A cos^3 theta) over the film (uniform on the image plane), 0 outside it.
    float pdf_direction(const Ray& ray) const override;
    // The importance arriving at `reference` from the pinhole (see CameraImportanceSample);
    // nothing when the point is behind the camera or projects outside the film. The pinhole
    // has no area, so `u` is not used.
    std::optional<CameraImportanceSample> sample_wi(const Vec3& reference, const Vec2& u) const override;
};
// END BOOK

}  // namespace freezeray::ch04
