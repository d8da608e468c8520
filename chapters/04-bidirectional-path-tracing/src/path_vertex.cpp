// Path vertices and their densities (book chapter 04; Veach 1997, sections 8.2 and 10.2;
// pbrt-v3, section 16.3.1).
#include "freezeray/ch04/path_vertex.hpp"

#include "freezeray/ch04/light_tracer.hpp"

#include <cmath>

namespace freezeray::ch04 {

bool PathVertex::connectible() const {
    switch (type) {
    case VertexType::Camera: return true;
    case VertexType::Light: return light != nullptr && light->type() != LightType::DeltaDirection;
    case VertexType::Surface: return bsdf != nullptr && (bsdf->flags() & (BSDF_Diffuse | BSDF_Glossy)) != 0;
    }
    return false;
}

Separation separation(const PathVertex& from, const PathVertex& to) {
    const Vec3 d = to.position - from.position;
    const float distance_squared = glm::dot(d, d);
    if (!(distance_squared > 0.0f)) return {Vec3(0.0f), 0.0f};
    const Vec3 direction = d / std::sqrt(distance_squared);
    if (from.infinite || to.infinite) return {direction, 1.0f};
    return {direction, 1.0f / distance_squared};
}

// BOOK(convert-density)
float convert_density(float pdf_solid_angle, const PathVertex& from, const PathVertex& to) {
    if (to.infinite) return pdf_solid_angle;  // a direction: solid angle is its measure
    const Separation s = separation(from, to);
    float pdf = pdf_solid_angle * s.inverse_distance_squared;
    if (to.on_surface()) pdf *= std::abs(glm::dot(to.geometric_normal, s.direction));
    return pdf;
}
// END BOOK

// BOOK(vertex-f)
Spectrum vertex_f(const PathVertex& v, const PathVertex& next) {
    if (v.type != VertexType::Surface) return Spectrum(0.0f);
    const Vec3 wi = separation(v, next).direction;
    if (wi == Vec3(0.0f)) return Spectrum(0.0f);
    if (v.transport == Transport::Radiance)  // light arrives from `next`, leaves along wo
        return v.bsdf->eval(v.frame.to_local(v.wo), v.frame.to_local(wi));
    // A light subpath: light arrives along wo and leaves towards `next` (chapter 04's
    // connect_to_camera says why no eta^2 is needed here, and what the correction is).
    return v.bsdf->eval(v.frame.to_local(wi), v.frame.to_local(v.wo)) *
           shading_normal_correction(v.wo, wi, v.frame.n, v.hit.geometric_normal);
}
// END BOOK

float light_pdf(const PathVertex& v, const PathVertex& next) {
    if (v.light == nullptr) return 0.0f;
    const Separation s = separation(v, next);
    float pdf;
    if (v.infinite) {
        // Rays from infinity start on a disk covering the scene: the area density of the disk
        // point, projected on `next` by the cosine below (pbrt-v3, Vertex::PdfLight).
        pdf = v.light->pdf_le(Ray{v.position, s.direction}, Vec3(0.0f)).position;
    } else {
        pdf = v.light->pdf_le(Ray{v.position, s.direction}, v.geometric_normal).direction * s.inverse_distance_squared;
    }
    if (next.on_surface()) pdf *= std::abs(glm::dot(next.geometric_normal, s.direction));
    return pdf;
}

float light_origin_pdf(const ch03::FixedLightSampler& lights, const PathVertex& v, const PathVertex& next) {
    if (v.light == nullptr) return 0.0f;
    const float choice = lights.probability(*v.light);
    const Vec3 w = separation(v, next).direction;  // the direction light travels
    if (v.light->type() == LightType::DeltaDirection) return 0.0f;
    if (v.infinite) return choice * v.light->pdf_li(next.position, -w);
    return choice * v.light->pdf_le(Ray{v.position, w}, v.geometric_normal).position;
}

float vertex_pdf(const Scene& scene, const PathVertex& v, const PathVertex* previous, const PathVertex& next) {
    if (v.type == VertexType::Light) return light_pdf(v, next);
    const Vec3 wn = separation(v, next).direction;
    if (wn == Vec3(0.0f)) return 0.0f;
    float pdf = 0.0f;
    if (v.type == VertexType::Camera) {
        pdf = scene.camera->pdf_direction(Ray{v.position, wn});
    } else {
        if (previous == nullptr) return 0.0f;
        const Vec3 wp = separation(v, *previous).direction;
        pdf = v.bsdf->pdf(v.frame.to_local(wp), v.frame.to_local(wn));
    }
    return convert_density(pdf, v, next);
}

Spectrum vertex_le(const Scene& scene, const PathVertex& v, const PathVertex& next) {
    if (v.light == nullptr) return Spectrum(0.0f);
    const Vec3 w = separation(v, next).direction;  // from the emitter towards `next`
    if (v.infinite) return v.light->le(-w);        // the escaping ray's direction
    if (v.type == VertexType::Surface) return emitted_radiance(scene.material(v.hit), v.hit, w);
    return Spectrum(0.0f);
}

namespace {

// Where a segment leaving `v` towards `target` starts: off the surface on the side it leaves by.
Vec3 segment_origin(const PathVertex& v, const Vec3& target) {
    if (v.type == VertexType::Surface)
        return offset_ray_origin(v.position, v.hit.position_error, v.hit.geometric_normal, target - v.position);
    if (v.type == VertexType::Light && v.on_surface())
        return offset_ray_origin(v.position, emission_origin_error(v.position), v.geometric_normal, target - v.position);
    return v.position;
}

}  // namespace

bool mutually_visible(const Scene& scene, const PathVertex& a, const PathVertex& b) {
    if (a.infinite && b.infinite) return false;
    if (a.infinite || b.infinite) {
        const PathVertex& finite = a.infinite ? b : a;
        const PathVertex& far = a.infinite ? a : b;
        const Vec3 direction = separation(finite, far).direction;
        return !scene.occluded(Ray{segment_origin(finite, finite.position + direction), direction});
    }
    const Vec3 from = segment_origin(a, b.position);
    const Vec3 to = segment_origin(b, a.position);
    const Vec3 d = to - from;
    const float distance = glm::length(d);
    if (!(distance > 0.0f)) return false;
    return !scene.occluded(Ray{from, d / distance, distance * (1.0f - 1e-4f)});
}

// BOOK(geometry-term)
float geometry_term(const Scene& scene, const PathVertex& a, const PathVertex& b) {
    const Separation s = separation(a, b);
    float g = s.inverse_distance_squared;
    if (a.type == VertexType::Surface) g *= std::abs(glm::dot(a.frame.n, s.direction));
    if (b.type == VertexType::Surface) g *= std::abs(glm::dot(b.frame.n, s.direction));
    if (g == 0.0f || !mutually_visible(scene, a, b)) return 0.0f;
    return g;
}
// END BOOK

}  // namespace freezeray::ch04
