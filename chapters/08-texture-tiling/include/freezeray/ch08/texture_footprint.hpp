// The footprint of a pixel in texture space: how far the texture coordinates move when the
// image moves by one pixel. A texture seen from far away or at a grazing angle packs many texels
// into one pixel; chapter 08 averages them beforehand (MIP maps) and picks the average of the
// right size from this footprint. The layouts that filter by it give it to the scene
// (TextureStorageMaker::footprint), which calls it for hits on textured materials.
#pragma once

#include "freezeray/camera.hpp"
#include "freezeray/hit.hpp"
#include "freezeray/mesh.hpp"

namespace freezeray::ch08 {

// Sets hit.duv_dx and hit.duv_dy: the change of hit.uv between neighbouring pixels, as if the
// hit were seen from the camera at the centre of the image. Two rays from the pinhole, one
// pixel's angle (camera.pixel_spread()) apart from the ray through the hit, meet the triangle's
// plane at offsets dp/dx and dp/dy from the hit (Igehy, "Tracing Ray Differentials", 1999;
// the same approximation for every hit, whatever path led there, as pbrt-v4's
// Camera::Approximate_dp_dxy: Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed.,
// 2023, section 5.2.3). The offsets are written in the triangle's barycentric coordinates, and
// those carry over to its texture coordinates linearly.
//
// One pixel, whatever the number of samples per pixel: pbrt shrinks the footprint as samples
// grow (by max(1/8, 1/sqrt(spp))), which makes the converged image depend on the sample count;
// FreezeRay's comparisons need every render of a scene to converge to the same image.
// A footprint that cannot be found (a ray parallel to the plane, a hit at the pinhole) is the
// whole texture (1 in u and v); a triangle whose texture coordinates do not vary gets zero.
void add_texture_footprint(Hit& hit, const TriangleMesh& mesh, const Camera& camera);

}  // namespace freezeray::ch08
