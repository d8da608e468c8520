// A vertex of a bidirectional subpath, with the two densities that multiple importance sampling
// over all strategies needs (Veach 1997, section 10.2; Veach and Guibas 1995; pbrt-v3,
// section 16.3.1, whose Vertex this follows).
#pragma once

#include "freezeray/bsdf.hpp"
#include "freezeray/hit.hpp"
#include "freezeray/light.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/ch03/fixed_light_sampler.hpp"

namespace freezeray::ch04 {

enum class VertexType {
    Camera,   // the pinhole: the first vertex of a camera subpath, or the camera sampled by t = 1
    Light,    // a point on a light (the first vertex of a light subpath, or the light sampled by
              // s = 1), or the environment a camera subpath escaped to
    Surface,  // a scattering point on a surface (it may also emit: see `light`)
};

// Which way a subpath was traced: camera subpaths carry radiance, light subpaths importance
// (their BSDFs are adjoint: shading-normal correction, Veach 1997, section 5.3).
enum class Transport { Radiance, Importance };

// BOOK(path-vertex)
struct PathVertex {
    VertexType type = VertexType::Surface;
    Transport transport = Transport::Radiance;
    // The subpath's throughput up to this vertex: the product of everything sampled before it
    // divided by its densities (alpha in Veach 1997, section 10.2).
    Spectrum beta{0.0f};
    Vec3 position{0.0f};          // for a light at infinity: a point along the direction light comes from
    Vec3 geometric_normal{0.0f};  // zero where there is no surface (pinhole, point light, infinity)
    Hit hit;                      // surfaces
    const BSDF* bsdf = nullptr;   // surfaces
    Frame frame;                  // surfaces: the shading frame, facing `wo` when two-sided
    Vec3 wo{0.0f};                // surfaces: unit direction towards the previous vertex of the subpath
    const Light* light = nullptr; // Light vertices, and surfaces that emit (their area light)
    bool delta = false;           // the scattering sampled here was a delta lobe
    bool infinite = false;        // a light at infinity (environment or directional)
    // Area densities of this vertex: pdf_fwd as its own subpath sampled it, pdf_rev as the other
    // subpath would have (from the next vertex). Solid-angle densities for a light at infinity.
    float pdf_fwd = 0.0f;
    float pdf_rev = 0.0f;

    bool on_surface() const { return geometric_normal != Vec3(0.0f); }
    bool is_light() const { return light != nullptr; }
    bool is_delta_light() const { return type == VertexType::Light && light != nullptr && freezeray::is_delta_light(light->type()); }
    // True when a deterministic connection can end here: a BSDF with a non-delta lobe, a light
    // that is not a single direction, the pinhole.
    bool connectible() const;
};
// END BOOK

// The reciprocal square distance between two vertices and the unit direction from `from` to
// `to`; for a light at infinity the direction alone (distance factor 1).
struct Separation {
    Vec3 direction;
    float inverse_distance_squared;
};
Separation separation(const PathVertex& from, const PathVertex& to);

// Turns a solid-angle density at `from` of the direction towards `to` into an area density at
// `to`: times |cos theta_to| / distance^2 (Veach 1997, eq. 8.10); unchanged when `to` is at
// infinity, where densities stay in solid angle.
float convert_density(float pdf_solid_angle, const PathVertex& from, const PathVertex& to);

// f at `v` for light travelling between `previous` and `next` (radiance convention: the BSDF of
// light arriving from the light's side and leaving towards the camera's), with the shading-
// normal correction of an importance-carrying vertex. Surfaces only.
Spectrum vertex_f(const PathVertex& v, const PathVertex& next);

// The area density with which `v`, reached from `previous`, samples `next`: its BSDF for a
// surface, the camera's direction density for the pinhole, the light's emission for a light.
// `previous` is ignored by the pinhole and lights (and may then be null).
float vertex_pdf(const Scene& scene, const PathVertex& v, const PathVertex* previous, const PathVertex& next);

// The area density with which a light subpath starting at light vertex `v` chooses `next` as
// its second vertex (the emission direction).
float light_pdf(const PathVertex& v, const PathVertex& next);

// The density with which a light subpath starts at `v` (light choice times the position's
// area density; for a light at infinity, light choice times the direction's solid-angle density).
float light_origin_pdf(const ch03::FixedLightSampler& lights, const PathVertex& v, const PathVertex& next);

// The radiance `v` emits towards `next` (an emitting surface, or the environment).
Spectrum vertex_le(const Scene& scene, const PathVertex& v, const PathVertex& next);

// True when nothing blocks the segment between the two vertices.
bool mutually_visible(const Scene& scene, const PathVertex& a, const PathVertex& b);

// The geometry term G (Veach 1997, eq. 8.3) with visibility, cosines at the shading normals as
// pbrt-v3's G (the geometric ones enter through vertex_f's correction).
float geometry_term(const Scene& scene, const PathVertex& a, const PathVertex& b);

}  // namespace freezeray::ch04
