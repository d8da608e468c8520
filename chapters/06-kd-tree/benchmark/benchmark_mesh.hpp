// The mesh the ray benchmark measures on: one OBJ file as ONE TriangleMesh whose triangle i is
// the i-th triangle tinyobjloader makes of the file, so that hits can be compared by index with
// any other tool that reads the file the same way.
#pragma once

#include "freezeray/mesh.hpp"

#include <string>

namespace freezeray::benchmark {

// Loads every face of the OBJ file with tinyobjloader's own triangulation (LoadObj with
// triangulate = true), in the order the faces are written, into one mesh: positions only
// (exactly the file's vertex list), every triangle kept, degenerate ones included, and every
// face_materials entry 0. Materials, normals and texture coordinates are ignored.
//
// Why not the renderer's load_obj (common/scene-input/src/obj_loader.cpp)? It fans polygons around their
// first corner, drops triangles without area and splits the file into one mesh per object;
// each of these changes the triangle numbering. FRHITS01 files and the shared ray batches
// (../shared/rays/README.md) number triangles globally in tinyobjloader's triangulate = true
// order (Debian 12's tinyobjloader 2.0.0rc10 cuts a quad along its shorter diagonal, and a
// larger polygon by ear clipping), so this loader keeps that numbering. A degenerate triangle
// has no area, so no ray hits it: keeping it changes the numbering, not the answers.
//
// Throws InputError("file.obj:LINE", ...) for malformed text or a face index out of range (the
// renderer's own first pass, obj_text_check), and for a vertex written as nan or inf.
TriangleMesh load_benchmark_mesh(const std::string& path);

}  // namespace freezeray::benchmark
