// Making the three batches of rays from a camera, as ../shared/rays/README.md describes the
// shared Sponza batches: primary rays through pixel centres, then from each primary hit one
// diffuse ray (cosine-weighted) and one shadow ray (to a uniform random point in the bounds).
#pragma once

#include "ray_batch.hpp"

#include "freezeray/accelerator.hpp"
#include "freezeray/camera.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>

namespace freezeray::benchmark {

// The camera of the shared Sponza batches: eye (1150, 180, -40), look-at (0, 300, -40), up +y,
// vertical field of view 75 degrees, 512 x 512 pixels.
CameraDescription shared_batches_camera();

struct RayGenerationSettings {
    CameraDescription camera = shared_batches_camera();
    std::uint64_t seed = 1;
    // At most this many rays of each kind. The batches made with a limit are the first `limit`
    // rays of the batches made without one (each pixel has its own random stream), so a limit
    // only saves time.
    std::size_t limit = std::numeric_limits<std::size_t>::max();
};

// Makes the batches, finding the primary hits with `accelerator` (built over the meshes whose
// bounds are `bounds`).
// - primary: one ray through the centre of each pixel, in scanline order, row 0 at the top.
// - diffuse: one per primary hit, in primary order. Its origin is the hit point moved along the
//   geometric normal, turned to face the incoming ray, by 1e-4 times the length of the bounds'
//   diagonal; its direction is cosine-weighted around that normal; tmax = +inf.
// - shadow: one per primary hit, from the same origin to a uniform random point of the
//   bounds; tmax = the distance to that point.
// Every random number of pixel p comes from make_chain_stream(seed, p): the batches depend on
// the seed only, not on the order in which pixels are traced.
RayBatches generate_ray_batches(const Accelerator& accelerator, const Bounds3& bounds,
                                const RayGenerationSettings& settings);

// The hit's geometric normal, turned to the side the ray came from.
Vec3 facing_normal(const Hit& hit, const Vec3& incoming_direction);

// The origin of the diffuse and shadow rays leaving a primary hit (see generate_ray_batches).
Vec3 secondary_ray_origin(const Hit& hit, const Vec3& incoming_direction, const Bounds3& bounds);

}  // namespace freezeray::benchmark
