// OBJ/MTL loading (common/scene-input/src/obj_loader.cpp) and mesh transforms (common/core/src/mesh.cpp).
// The fixtures are the small files in tests/data/obj/; each starts with a comment saying what
// it is for.
#include "freezeray/error.hpp"
#include "freezeray/mesh.hpp"
#include "freezeray/obj_loader.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>

#ifndef FREEZERAY_SOURCE_DIR
#define FREEZERAY_SOURCE_DIR "."
#endif

using namespace freezeray;
using Catch::Matchers::Contains;

namespace {

std::string fixture(const std::string& name) { return std::string(FREEZERAY_SOURCE_DIR) + "/tests/data/obj/" + name; }

// The message of the InputError that loading a fixture must throw.
std::string load_error(const std::string& name) {
    try {
        load_obj(fixture(name));
    } catch (const InputError& error) {
        return error.what();
    }
    FAIL("loading " << name << " did not throw InputError");
    return {};
}

// The unit normal on the front side of a triangle: the side from which it turns counter-clockwise.
Vec3 front_normal(const TriangleMesh& mesh, std::size_t triangle) {
    const auto& [a, b, c] = mesh.triangles[triangle];
    const Vec3& p = mesh.positions[a];
    return glm::normalize(glm::cross(mesh.positions[b] - p, mesh.positions[c] - p));
}

bool close_to(const Vec3& a, const Vec3& b, float tolerance = 1e-6f) { return glm::length(a - b) <= tolerance; }

const MtlMaterial& material_named(const ObjLoadResult& result, const std::string& name) {
    for (const MtlMaterial& material : result.materials)
        if (material.name == name) return material;
    FAIL("no material named " << name);
    return result.materials.front();
}

}  // namespace

TEST_CASE("a quad becomes two fan triangles with its winding kept", "[unit][obj]") {
    const ObjLoadResult result = load_obj(fixture("quad.obj"));
    REQUIRE(result.meshes.size() == 1);
    const TriangleMesh& quad = result.meshes[0];
    CHECK(quad.name == "quad");
    REQUIRE(quad.positions.size() == 4);
    CHECK(quad.positions[2] == Vec3(1, 1, 0));
    REQUIRE(quad.triangle_count() == 2);
    // A fan around the first corner: (1 2 3) and (1 3 4). (tinyobjloader's own triangulation
    // would cut this square along the other diagonal.)
    CHECK(quad.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(quad.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
    CHECK(close_to(front_normal(quad, 0), Vec3(0, 0, 1)));
    CHECK(close_to(front_normal(quad, 1), Vec3(0, 0, 1)));
    CHECK(quad.normals.empty());
    CHECK(quad.uvs.empty());
}

TEST_CASE("a polygon with more corners is fanned around its first corner", "[unit][obj]") {
    const TriangleMesh pentagon = load_obj(fixture("pentagon.obj")).meshes.at(0);
    REQUIRE(pentagon.triangle_count() == 3);
    CHECK(pentagon.triangles[2] == std::array<std::uint32_t, 3>{0, 3, 4});
    for (std::size_t t = 0; t < 3; ++t) CHECK(close_to(front_normal(pentagon, t), Vec3(0, 0, 1)));
}

TEST_CASE("vertices are shared by corners with the same (v, vt, vn) triple", "[unit][obj]") {
    const TriangleMesh cube = load_obj(fixture("cube.obj")).meshes.at(0);
    CHECK(cube.triangle_count() == 12);
    // 8 positions, but each corner of the cube meets 3 faces with different normals.
    CHECK(cube.positions.size() == 24);
    CHECK(cube.normals.size() == 24);
    CHECK(cube.uvs.size() == 24);
    for (std::size_t t = 0; t < cube.triangle_count(); ++t) {
        // The written normals face outwards, and so does the front side of every triangle.
        for (const std::uint32_t v : cube.triangles[t]) CHECK(close_to(cube.normals[v], front_normal(cube, t)));
    }
    CHECK(cube.bounds().min == Vec3(0, 0, 0));
    CHECK(cube.bounds().max == Vec3(1, 1, 1));
}

TEST_CASE("a corner without a normal in a shape with normals gets the geometric normal", "[unit][obj]") {
    const TriangleMesh mesh = load_obj(fixture("partial_normals.obj")).meshes.at(0);
    REQUIRE(mesh.triangle_count() == 2);
    REQUIRE(mesh.normals.size() == mesh.positions.size());
    for (const std::uint32_t v : mesh.triangles[0]) CHECK(close_to(mesh.normals[v], Vec3(0, 0.6f, 0.8f)));
    for (const std::uint32_t v : mesh.triangles[1]) CHECK(close_to(mesh.normals[v], Vec3(0, 0, 1)));
}

TEST_CASE("each object is a mesh and each triangle has its material", "[unit][obj]") {
    const ObjLoadResult result = load_obj(fixture("two_objects.obj"));
    REQUIRE(result.materials.size() == 2);  // no default: every face has a material
    CHECK(result.materials[0].name == "red");
    CHECK(result.materials[1].name == "blue");
    REQUIRE(result.meshes.size() == 2);
    CHECK(result.meshes[0].name == "left");
    CHECK(result.meshes[0].face_materials == std::vector<std::uint32_t>{0});
    CHECK(result.meshes[1].name == "right");
    CHECK(result.meshes[1].face_materials == std::vector<std::uint32_t>{1, 0});
}

TEST_CASE("faces without a material get a default material appended", "[unit][obj]") {
    const ObjLoadResult result = load_obj(fixture("no_material.obj"));
    REQUIRE(result.materials.size() == 3);
    const MtlMaterial& fallback = result.materials[2];
    CHECK(fallback.name == "default");
    CHECK(fallback.kd == Spectrum(0.5f));
    CHECK_THAT(fallback.where, Contains("no_material.obj"));
    REQUIRE(result.meshes.size() == 1);
    CHECK(result.meshes[0].name == "no_material");  // no o or g line: named after the file
    CHECK(result.meshes[0].face_materials == std::vector<std::uint32_t>{2, 1});

    // Without any MTL file, the default is the only material.
    const ObjLoadResult quad = load_obj(fixture("quad.obj"));
    REQUIRE(quad.materials.size() == 1);
    CHECK(quad.materials[0].name == "default");
}

TEST_CASE("MTL values are read as written", "[unit][obj]") {
    const ObjLoadResult result = load_obj(fixture("materials.obj"));
    REQUIRE(result.materials.size() == 4);

    const MtlMaterial& lamp = material_named(result, "lamp");
    CHECK_THAT(lamp.where, Contains("materials.mtl:2"));
    CHECK(close_to(lamp.kd, Vec3(0.1f, 0.2f, 0.3f)));
    CHECK(close_to(lamp.ks, Vec3(0.4f, 0.5f, 0.6f)));
    CHECK(close_to(lamp.ke, Vec3(10, 20, 30)));
    CHECK(close_to(lamp.tf, Vec3(0.9f, 0.8f, 0.7f)));
    CHECK(lamp.ns == Approx(250));
    CHECK(lamp.ni == Approx(1.45));
    CHECK(lamp.dissolve == Approx(0.75));
    CHECK(lamp.illum == 7);
    REQUIRE(lamp.pr.has_value());
    CHECK(*lamp.pr == Approx(0.3));
    REQUIRE(lamp.pm.has_value());
    CHECK(*lamp.pm == Approx(1));

    // What a block does not write keeps MtlMaterial's defaults; Pr and Pm stay absent.
    const MtlMaterial& plain = material_named(result, "plain");
    CHECK_THAT(plain.where, Contains("materials.mtl:14"));
    CHECK_FALSE(plain.pr.has_value());
    CHECK_FALSE(plain.pm.has_value());
    CHECK(plain.illum == 2);
    CHECK(plain.tf == Spectrum(1.0f));
    CHECK(plain.ke == Spectrum(0.0f));
    CHECK(plain.map_kd.empty());

    // "Kd 0.25" is short for "Kd 0.25 0.25 0.25".
    CHECK(close_to(material_named(result, "grey").kd, Vec3(0.25f)));
}

TEST_CASE("texture maps are resolved to absolute paths of existing files", "[unit][obj]") {
    const MtlMaterial textured = material_named(load_obj(fixture("materials.obj")), "textured");
    const std::filesystem::path checker = std::filesystem::path(textured.map_kd);
    CHECK(checker.is_absolute());
    CHECK(std::filesystem::is_regular_file(checker));
    CHECK(std::filesystem::equivalent(checker, fixture("textures/checker.png")));
    // Options before the file name ("-bm 0.5") are not part of it.
    CHECK(textured.map_bump == textured.map_kd);
}

TEST_CASE("one mtllib line can name several MTL files", "[unit][obj]") {
    const ObjLoadResult result = load_obj(fixture("two_mtllibs.obj"));
    CHECK(result.materials.size() == 6);
    const std::vector<std::uint32_t>& materials = result.meshes.at(0).face_materials;
    REQUIRE(materials.size() == 2);
    CHECK(result.materials[materials[0]].name == "blue");
    CHECK(result.materials[materials[1]].name == "lamp");
}

TEST_CASE("degenerate triangles are dropped and counted, tiny ones kept", "[unit][obj]") {
    const ObjLoadResult result = load_obj(fixture("degenerate.obj"));
    CHECK(result.dropped_degenerate_triangles == 5);
    REQUIRE(result.warnings.size() == 1);
    CHECK_THAT(result.warnings[0], Contains("5 degenerate"));
    REQUIRE(result.meshes.size() == 1);
    const TriangleMesh& mesh = result.meshes[0];
    REQUIRE(mesh.triangle_count() == 2);
    CHECK(mesh.triangle_area(0) == Approx(0.5));
    // Edges of 2^-14 along x and y: area 2^-29.
    CHECK(mesh.triangle_area(1) == Approx(std::ldexp(1.0, -29)));
}

TEST_CASE("bad OBJ input is reported with its file and line", "[unit][obj]") {
    SECTION("a face index past the last vertex") {
        const std::string message = load_error("bad_index.obj");
        CHECK_THAT(message, Contains("bad_index.obj:6"));
        CHECK_THAT(message, Contains("face index 57 is out of range (the file has 3 vertices)"));
    }
    SECTION("a negative face index reaching before the first vertex") {
        const std::string message = load_error("bad_negative_index.obj");
        CHECK_THAT(message, Contains("bad_negative_index.obj:6"));
        CHECK_THAT(message, Contains("face index -4"));
    }
    SECTION("a face index 0") { CHECK_THAT(load_error("bad_zero_index.obj"), Contains("bad_zero_index.obj:5")); }
    SECTION("a texture coordinate index out of range") {
        const std::string message = load_error("bad_uv_index.obj");
        CHECK_THAT(message, Contains("bad_uv_index.obj:8"));
        CHECK_THAT(message, Contains("texture coordinate index 5"));
    }
    SECTION("a vertex with a missing coordinate") {
        CHECK_THAT(load_error("bad_missing_coordinate.obj"), Contains("bad_missing_coordinate.obj:3"));
    }
    SECTION("a letter where a number belongs") {
        const std::string message = load_error("bad_number.obj");
        CHECK_THAT(message, Contains("bad_number.obj:4"));
        CHECK_THAT(message, Contains("'x'"));
    }
    SECTION("a file cut in the middle of a face") {
        CHECK_THAT(load_error("truncated.obj"), Contains("truncated.obj:7"));
    }
    SECTION("a file without faces") {
        const std::string message = load_error("empty.obj");
        CHECK_THAT(message, Contains("empty.obj"));
        CHECK_THAT(message, Contains("has no faces"));
    }
    SECTION("a file that does not exist") {
        CHECK_THAT(load_error("no_such_file.obj"), Contains("no_such_file.obj"));
    }
}

TEST_CASE("bad material references are reported with their file and line", "[unit][obj]") {
    SECTION("an mtllib naming a missing file") {
        const std::string message = load_error("missing_mtllib.obj");
        CHECK_THAT(message, Contains("missing_mtllib.obj:2"));
        CHECK_THAT(message, Contains("nowhere.mtl"));
    }
    SECTION("a usemtl naming an undefined material") {
        const std::string message = load_error("unknown_usemtl.obj");
        CHECK_THAT(message, Contains("unknown_usemtl.obj:6"));
        CHECK_THAT(message, Contains("green"));
    }
    SECTION("a malformed value in an MTL file") {
        const std::string message = load_error("bad_value.obj");
        CHECK_THAT(message, Contains("bad_value.mtl:3"));
        CHECK_THAT(message, Contains("Kd"));
    }
    SECTION("a map_Kd naming a missing texture") {
        const std::string message = load_error("missing_map.obj");
        CHECK_THAT(message, Contains("missing_map.mtl:4"));
        CHECK_THAT(message, Contains("no_such_texture.png"));
    }
}

TEST_CASE("a transform moves positions and normals and keeps the front side", "[unit][obj]") {
    TriangleMesh mesh;
    mesh.name = "triangle";
    mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.normals = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)};
    mesh.triangles = {{0, 1, 2}};
    mesh.face_materials = {0};
    REQUIRE(close_to(front_normal(mesh, 0), Vec3(0, 0, 1)));

    SECTION("translation and non-uniform scale") {
        const Mat4 matrix = glm::scale(glm::translate(Mat4(1.0f), Vec3(5, 0, 0)), Vec3(2, 3, 4));
        mesh.transform(matrix);
        CHECK(close_to(mesh.positions[1], Vec3(7, 0, 0)));
        CHECK(close_to(mesh.normals[0], Vec3(0, 0, 1)));
        CHECK(mesh.triangle_area(0) == Approx(3.0));
        CHECK(close_to(mesh.bounds().max, Vec3(7, 3, 0)));
    }
    SECTION("a shear: normals by the inverse transpose stay perpendicular to the surface") {
        Mat4 shear(1.0f);
        shear[0][2] = 1.0f;  // z += x
        mesh.transform(shear);
        CHECK(glm::dot(mesh.normals[0], mesh.positions[1] - mesh.positions[0]) == Approx(0).margin(1e-6));
        CHECK(close_to(front_normal(mesh, 0), mesh.normals[0]));
    }
    SECTION("a mirror through z = 0 turns the front side to -z") {
        mesh.transform(glm::scale(Mat4(1.0f), Vec3(1, 1, -1)));
        CHECK(close_to(mesh.normals[0], Vec3(0, 0, -1)));
        CHECK(close_to(front_normal(mesh, 0), Vec3(0, 0, -1)));
    }
    SECTION("a mirror through x = 0 keeps the front side on +z") {
        mesh.transform(glm::scale(Mat4(1.0f), Vec3(-1, 1, 1)));
        CHECK(close_to(mesh.positions[1], Vec3(-1, 0, 0)));
        CHECK(close_to(mesh.normals[0], Vec3(0, 0, 1)));
        CHECK(close_to(front_normal(mesh, 0), Vec3(0, 0, 1)));
    }
    SECTION("a matrix that flattens the mesh is refused") {
        CHECK_THROWS_AS(mesh.transform(glm::scale(Mat4(1.0f), Vec3(1, 1, 0))), InputError);
    }
}

TEST_CASE("the shared Cornell box loads with its 36 triangles", "[unit][obj]") {
    const std::optional<std::string> scenes = testing::shared_scenes_folder();
    const std::string path = scenes.value_or("(no shared scenes folder)") + "/cornell-box/cornell-box.obj";
    if (!scenes || !std::filesystem::exists(path)) {
        WARN("skipped: " << path << " is not there (set FREEZERAY_SHARED_SCENES)");
        return;
    }
    const ObjLoadResult result = load_obj(path);
    std::size_t triangles = 0;
    for (const TriangleMesh& mesh : result.meshes) triangles += mesh.triangle_count();
    CHECK(triangles == 36);
    CHECK(result.dropped_degenerate_triangles == 0);
}

// Found by fuzz_obj: the first pass must read lines and numbers as tinyobjloader does, or a face
// index it accepted could point past tinyobjloader's vertices.
TEST_CASE("OBJ and MTL lines end at a lone carriage return and huge exponents are refused", "[unit][obj]") {
    const std::string folder = (std::filesystem::temp_directory_path() /
                                ("freezeray-obj-lines-" + std::to_string(std::random_device()()))).string();
    std::filesystem::create_directories(folder);
    const auto load_text = [&](const std::string& name, const std::string& text) {
        std::ofstream(folder + "/" + name, std::ios::binary) << text;
        try {
            load_obj(folder + "/" + name);
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("(loaded)");
    };
    // "v\r 0 1 0" is two lines for tinyobjloader, "v" and " 0 1 0": no third vertex.
    CHECK_THAT(load_text("cr.obj", "v 0 0 0\nv 1 0 0\nv\r 0 1 0\nf 1 2 3\n"), Contains("cr.obj:3"));
    // Old Mac line endings alone are fine.
    CHECK(load_text("mac.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r") == "(loaded)");
    // Text after a NUL byte is not part of the line for tinyobjloader.
    CHECK_THAT(load_text("nul.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\0 4\n", 35) + "f 1 2 4\n"),
               Contains("nul.obj:5") && Contains("out of range"));
    CHECK_THAT(load_text("exponent.obj", "v 0 0 1e-21474836491\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
               Contains("exponent.obj:1") && Contains("exponent too large"));
    // Vertex weights (a tinyobjloader extension): their joint ids become ints.
    CHECK(load_text("weights.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 0 0 0.25 1 0.75\nf 1 2 3\n") == "(loaded)");
    CHECK_THAT(load_text("bad-weights.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 0 1e999 1\nf 1 2 3\n"),
               Contains("bad-weights.obj:4") && Contains("'vw'"));
    std::ofstream(folder + "/exponent.mtl") << "Ka 1e2147483649 0 0\nnewmtl m\nKd 1 1 1\n";
    CHECK_THAT(load_text("uses-mtl.obj", "mtllib exponent.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n"),
               Contains("exponent.mtl:1"));
    std::filesystem::remove_all(folder);
}
