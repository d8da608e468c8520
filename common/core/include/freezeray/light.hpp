// Lights: emitters that an integrator can sample directly. The interface lives here so that a
// scene can hold its lights and every integrator can see an environment; the light classes and
// how they are sampled are chapter 03's subject (chapters/03-multiple-importance-sampling).
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/ray.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace freezeray {

// How a light's emission is distributed: delta lights (a point, one direction) cannot be hit by
// a ray and can only be found by sampling them; area and infinite lights can be both.
enum class LightType {
    DeltaPosition,   // point and spot lights
    DeltaDirection,  // directional lights
    Area,            // emissive triangles
    Infinite,        // environment maps and constant backgrounds
};

inline bool is_delta_light(LightType type) {
    return type == LightType::DeltaPosition || type == LightType::DeltaDirection;
}

// A direction towards a light, sampled from a reference point (sample_li).
struct LightSample {
    Spectrum radiance;  // Li: radiance arriving at the reference point along -wi, if unoccluded
    Vec3 wi;            // unit direction from the reference point towards the light
    // Solid-angle density of wi. For a delta light: 1, the probability of its only direction
    // (the estimator then divides by 1 and no MIS is possible).
    float pdf = 0.0f;
    Vec3 position;      // the sampled point on the light; unused for infinite and directional lights
    bool infinite = false;  // true when the light is at infinity (shadow ray without an end)
    Vec3 normal{0.0f};      // the light's surface normal at `position` (area lights; zero otherwise)
};

// A ray leaving a light, for tracing paths from the lights (sample_le, chapter 04).
struct LightEmissionSample {
    Ray ray;
    Vec3 normal;                 // surface normal at the origin (zero for point lights)
    Spectrum radiance;           // Le(origin, direction)
    float pdf_position = 0.0f;   // area density of the origin (1 for a delta position)
    float pdf_direction = 0.0f;  // solid-angle density of the direction (1 for a delta direction)
};

// The densities with which sample_le produces a given ray (Light::pdf_le).
struct EmissionDensity {
    float position = 0.0f;   // area density of the origin (0 for a delta position: no ray finds it)
    float direction = 0.0f;  // solid-angle density of the direction (0 for a delta direction)
};

class Light {
public:
    virtual ~Light() = default;

    virtual LightType type() const = 0;

    // Samples a direction towards the light as seen from `reference`; nothing when the light
    // sends no light there (the reference is behind a one-sided emitter, outside a spot's cone).
    virtual std::optional<LightSample> sample_li(const Vec3& reference, const Vec2& u) const = 0;

    // The solid-angle density with which sample_li from `reference` returns the direction wi;
    // 0 for delta lights and for directions that miss the light.
    virtual float pdf_li(const Vec3& reference, const Vec3& wi) const = 0;

    // Radiance arriving along a ray that leaves the scene (infinite lights only; black otherwise).
    virtual Spectrum le(const Vec3& direction) const { (void)direction; return Spectrum(0.0f); }

    // Samples a ray leaving the light (for light paths): u_position chooses the origin,
    // u_direction the direction.
    virtual std::optional<LightEmissionSample> sample_le(const Vec2& u_position, const Vec2& u_direction) const = 0;

    // The densities with which sample_le produces `ray` leaving the light from a point whose
    // normal is `normal` (bidirectional path tracing needs them for paths found another way,
    // chapter 04; pbrt-v3's Pdf_Le). For lights at infinity the position density is that of the
    // disk sample_le starts rays on, and the direction is the one light travels in.
    virtual EmissionDensity pdf_le(const Ray& ray, const Vec3& normal) const = 0;

    // Total emitted power (flux, W in the renderer's units), used to choose lights in
    // proportion to the light they send into the scene.
    virtual Spectrum power() const = 0;

    // Called once the scene's extent is known (lights at infinity need its bounding sphere).
    virtual void preprocess(const Bounds3& scene_bounds) { (void)scene_bounds; }

    std::uint32_t index = 0;  // position in Scene::lights
    std::string where;        // the file and JSON path (or mesh and triangle) it came from, for messages
};

}  // namespace freezeray
