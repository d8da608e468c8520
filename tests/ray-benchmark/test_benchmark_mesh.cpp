// The ray benchmark's OBJ loading (chapters/06-kd-tree/benchmark/benchmark_mesh.cpp): one mesh,
// triangles in tinyobjloader's triangulate = true order, degenerate ones kept, bad text refused.
#include "benchmark_mesh.hpp"

#include "freezeray/error.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;
using namespace freezeray::benchmark;
using Catch::Matchers::Contains;

namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::string load_error(const std::string& path) {
    try {
        load_benchmark_mesh(path);
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("benchmark mesh: quads are cut along their shorter diagonal, as tinyobjloader does", "[unit][ray-benchmark]") {
    testing::TemporaryFolder folder;
    // Three kites, each with one diagonal five times shorter than the other: corners 1-3
    // (0-based) in the first two, corners 0-2 in the third.
    const std::string path = folder.write("quads.obj",
                                          "v 0 0 0\nv 1 -0.2 0\nv 2 0 0\nv 1 0.2 0\n"  // short diagonal 2-4
                                          "v 0 0 1\nv 0.2 1 1\nv 0 2 1\nv -0.2 1 1\n"  // short diagonal 6-8
                                          "v 0 0 2\nv 0.2 -1 2\nv 0.4 0 2\nv 0.2 1 2\n" // short diagonal 9-11
                                          "f 1 2 3 4\nf 5 6 7 8\nf 9 10 11 12\n");
    const TriangleMesh mesh = load_benchmark_mesh(path);
    REQUIRE(mesh.triangle_count() == 6);
    // Diagonal 0-2 shorter: (0, 1, 2), (0, 2, 3); else (0, 1, 3), (1, 2, 3) (tinyobjloader 2.0.0rc10).
    CHECK(mesh.triangles[0] == Triangle{0, 1, 3});
    CHECK(mesh.triangles[1] == Triangle{1, 2, 3});
    CHECK(mesh.triangles[2] == Triangle{4, 5, 7});
    CHECK(mesh.triangles[3] == Triangle{5, 6, 7});
    CHECK(mesh.triangles[4] == Triangle{8, 9, 10});
    CHECK(mesh.triangles[5] == Triangle{8, 10, 11});
    CHECK(mesh.positions.size() == 12);
    CHECK(mesh.face_materials == std::vector<std::uint32_t>(6, 0u));
}

TEST_CASE("benchmark mesh: every object goes into one mesh in file order, degenerate triangles kept",
          "[unit][ray-benchmark]") {
    testing::TemporaryFolder folder;
    const std::string path = folder.write("objects.obj",
                                          "mtllib missing.mtl\n"
                                          "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\n"
                                          "o first\nusemtl red\nf 1 2 3\n"
                                          "f 1 2 4\n"  // collinear: no area, kept
                                          "vt 0 0\n"
                                          "o second\nusemtl blue\nf 3/1 2/1 1/1\nf 1 1 2\n");
    const TriangleMesh mesh = load_benchmark_mesh(path);
    REQUIRE(mesh.triangle_count() == 4);
    CHECK(mesh.triangles[0] == Triangle{0, 1, 2});
    CHECK(mesh.triangles[1] == Triangle{0, 1, 3});
    CHECK(mesh.triangles[2] == Triangle{2, 1, 0});
    CHECK(mesh.triangles[3] == Triangle{0, 0, 1});
    CHECK(mesh.normals.empty());
    CHECK(mesh.uvs.empty());
}

TEST_CASE("benchmark mesh: the Cornell box has its 16 quads as 32 triangles", "[unit][ray-benchmark]") {
    const TriangleMesh mesh = load_benchmark_mesh(testing::scene_path("cornell-box/cornell-box.obj"));
    CHECK(mesh.triangle_count() == 32);
}

TEST_CASE("benchmark mesh: bad files are refused with the file and line", "[unit][ray-benchmark]") {
    testing::TemporaryFolder folder;
    CHECK_THAT(load_error(folder.file("missing.obj")), Contains("missing.obj") && Contains("does not exist"));
    CHECK_THAT(load_error(folder.write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")),
               Contains("range.obj:4"));
    CHECK_THAT(load_error(folder.write("number.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n")),
               Contains("number.obj:2"));
    CHECK_THAT(load_error(folder.write("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n")),
               Contains("nan.obj") && Contains("vertex 2"));
    CHECK_THAT(load_error(folder.write("empty.obj", "v 0 0 0\n")), Contains("empty.obj") && Contains("no faces"));
}
