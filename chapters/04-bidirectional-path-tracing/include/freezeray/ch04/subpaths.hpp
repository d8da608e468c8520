// Camera and light subpaths of bidirectional path tracing (Veach 1997, section 10.2; pbrt-v3,
// section 16.3.2): random walks that record every vertex with its forward and reverse densities.
#pragma once

#include "freezeray/ch04/sample_stream.hpp"
#include "freezeray/scratch_arena.hpp"
#include "freezeray/ch04/path_vertex.hpp"

namespace freezeray::ch04 {

// The streams of a bidirectional sample (SampleStream::start_stream): the camera subpath (and
// the film position before it), the light subpath, the connections' light samples.
inline constexpr int CameraStream = 0;
inline constexpr int LightStream = 1;
inline constexpr int ConnectionStream = 2;
inline constexpr int BidirectionalStreamCount = 3;

// Traces a camera subpath along `camera_ray` into path[0 .. max_vertices), path[0] the pinhole;
// returns the vertex count. Reads the current stream (the caller starts CameraStream and takes
// the film position from it first). A ray that escapes ends the subpath on the environment (a Light
// vertex) when the scene has one.
int camera_subpath(const Scene& scene, const Ray& camera_ray, SampleStream& samples, ScratchArena& arena, int max_vertices,
                   PathVertex* path);

// Traces a light subpath into path[0 .. max_vertices): a light chosen by `lights`, a point and
// direction from its sample_le, then BSDF sampling with the adjoint BSDF, all from LightStream.
// Returns the count.
int light_subpath(const Scene& scene, const ch03::FixedLightSampler& lights, SampleStream& samples, ScratchArena& arena,
                  int max_vertices, PathVertex* path);

}  // namespace freezeray::ch04
