// Light tracing (`light-tracing`): paths traced from the lights, every vertex connected to the
// camera and splatted onto the film through the camera's importance We. These are the t = 1
// strategies of bidirectional path tracing alone, unweighted (Veach 1997, section 10.2; Arvo and
// Kirk 1990 "particle tracing"; pbrt-v3, section 16.3). Chapter 04's `bdpt` reuses its pieces.
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/hit.hpp"
#include "freezeray/integrator.hpp"
#include "freezeray/ch04/camera_importance.hpp"
#include "freezeray/ch04/light_path_loop.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/ch03/fixed_light_sampler.hpp"

#include <optional>

namespace freezeray::ch04 {

// A contribution to splat: where on the film, and how much (before dividing by the light paths
// per pixel, which the film does).
struct CameraConnection {
    Vec2 raster_position;
    Spectrum value;
};

// The factor that makes the BSDF adjoint when shading normals differ from geometric ones, for
// a particle (importance transport) arriving from wo and leaving along wi, both pointing away
// from the surface: |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|) (Veach 1997, section 5.3, eq. 5.19;
// pbrt-v3, section 16.1, "Non-symmetry due to shading normals"). 0 when wo or wi grazes the
// geometric surface.
float shading_normal_correction(const Vec3& wo, const Vec3& wi, const Vec3& shading_normal, const Vec3& geometric_normal);

// The factor that turns the weight of a BSDF sample drawn from the light's side (wo towards the
// light, wi the sampled direction, both in world space) into the adjoint BSDF's that a light
// path carries: the shading-normal correction, and eta^2 on transmission (radiance is compressed
// by refraction, importance is not; Veach 1997, section 5.2; pbrt-v3, section 16.1).
float adjoint_sample_factor(const BSDFSample& sample, const Vec3& wo, const Vec3& wi, const Vec3& shading_normal,
                            const Vec3& geometric_normal);

// A conservative bound on the rounding error of a point interpolated on a triangle: a light
// sample's origin has no Hit to carry one. Relative 2^-18, above float interpolation error
// (about 7 ulp, pbrt-v3, section 3.9.4), so a ray spawned there cannot hit its own emitter.
Vec3 emission_origin_error(const Vec3& point);

// Connects a light-path vertex on a surface to the camera (the t = 1 strategy): `beta` is the
// light path's throughput up to the vertex (Le cos / pdfs, times BSDF weights), wo_world the
// unit direction from the vertex back along the path towards the light, frame the vertex's
// shading frame. The value is beta f(camera <- wo) |cos| correction We / pdf; nothing when
// the camera cannot see the vertex or the BSDF sends nothing towards it.
std::optional<CameraConnection> connect_to_camera(const Scene& scene, const Hit& hit, const BSDF& bsdf, const Frame& frame,
                                                  const Vec3& wo_world, const Spectrum& beta);

// Connects the first vertex of a light path, on an area light, to the camera (s = 1, t = 1):
// the emitter seen directly.
std::optional<CameraConnection> connect_light_to_camera(const Scene& scene, const LightEmissionSample& emission,
                                                        float light_probability);

struct LightTracingSettings {
    int max_depth = 0;  // segments of the whole path, camera included; 0: chapter 02's default
};

class LightTracer final : public Integrator {
public:
    explicit LightTracer(const LightTracingSettings& settings);

    RenderResult render(const Scene& scene, const RenderSettings& settings, Progress& progress) const override;

    // Traces one light path and splats its connections to the camera into `splats`.
    void trace_light_path(const Scene& scene, const ch03::FixedLightSampler& lights, PCG32& random, ScratchArena& arena,
                          SplatBuffer& splats) const;

private:
    LightTracingSettings settings_;
};

}  // namespace freezeray::ch04
