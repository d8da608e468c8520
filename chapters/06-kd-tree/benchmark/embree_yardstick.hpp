// Embree 3 (Wald et al., "Embree: A Kernel Framework for Efficient CPU Ray Tracing", ACM TOG
// 33(4), 2014) as the yardstick the course's accelerators are measured against: a production
// BVH behind the same Accelerator interface, asked the same questions about the same triangles.
//
// Embree is optional. embree_yardstick.cpp is compiled when CMake finds it, embree_absent.cpp
// otherwise; only the ray-benchmark executable links it, never a renderer or chapter library,
// and it is never in the registry.
#pragma once

#include "built_accelerator.hpp"

#include "freezeray/mesh.hpp"

#include <optional>
#include <string>
#include <vector>

namespace freezeray::benchmark {

// Whether the benchmark was built with Embree.
bool embree_is_available();

// "Embree 3.13.5", or "Embree not found" when the benchmark was built without it.
std::string embree_description();

// Embree as an Accelerator, built and timed; nothing when the benchmark was built without it.
// One triangle geometry per mesh with the mesh's vertex and index buffers (geometry id = mesh
// index, primitive id = triangle index), built with RTC_BUILD_QUALITY_HIGH on one thread, as
// the course's accelerators build; its memory (the BVH and Embree's copy of the buffers) is
// counted by Embree's memory monitor. Queries are single rays, rtcIntersect1 and rtcOccluded1:
// the fair comparison for a tracer of single rays. A hit is filled in by make_hit from Embree's
// triangle, t and barycentrics, so Embree pays for the same Hit as the course's accelerators.
// Embree's default scene flags (not RTC_SCENE_FLAG_ROBUST): a ray through an edge may miss
// both triangles, which the disagreement counts then show. The meshes must outlive it. Throws
// std::runtime_error when Embree reports an error.
std::optional<BuiltAccelerator> build_embree(const std::vector<TriangleMesh>& meshes);

}  // namespace freezeray::benchmark
