// Scenes with lights (chapter 03): the "lights" array of every type, one area light per emissive
// triangle and the map from a hit back to it, and errors that name the JSON path (or the file).
#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <limits>

using namespace freezeray;
using freezeray::testing::TemporaryFolder;

namespace {

// A unit quad in the plane y = 1 facing down (-y), made of two emissive triangles, and a floor
// triangle at y = 0 painted grey; plus a 4 x 2 environment map. `lights` is the JSON of the
// "lights" array (or empty for none).
std::string make_scene(const TemporaryFolder& folder, const std::string& lights) {
    folder.write("room.mtl", "newmtl floor\nKd 0.5 0.5 0.5\n\nnewmtl lamp\nKd 0 0 0\nKe 4 4 4\n");
    folder.write("room.obj", "mtllib room.mtl\n"
                                        "v -2 0 -2\nv 2 0 -2\nv 0 0 2\n"            // floor
                                        "v 0 1 0\nv 1 1 0\nv 1 1 1\nv 0 1 1\n"      // lamp
                                        "o floor\nusemtl floor\nf 1 3 2\n"
                                        "o lamp\nusemtl lamp\nf 4 5 6\nf 4 6 7\n");
    Image sky(4, 2, Spectrum(0.5f));
    sky.at(1, 0) = Spectrum(20.0f);
    write_image(folder.file("sky.pfm"), sky);
    std::string text = R"({"camera": {"position": [0, 0.5, 5], "look_at": [0, 0.5, 0], "fov_vertical_degrees": 40, "resolution": [8, 4]},
        "meshes": [{"file": "room.obj"}])";
    if (!lights.empty()) text += ", \"lights\": " + lights;
    folder.write("scene.json", text + "}");
    return folder.file("scene.json");
}

}  // namespace

TEST_CASE("each light type of the lights array lands in scene.lights after the area lights", "[unit][scene][ch03]") {
    TemporaryFolder folder;
    const std::string path = make_scene(folder, R"([
        {"type": "point", "position": [0, 0.5, 0], "intensity": [1, 2, 3]},
        {"type": "spot", "position": [0, 0.9, 0], "look_at": [0, 0, 0], "intensity": 5, "cone_angle_degrees": 25},
        {"type": "directional", "direction": [0, -1, 0.2], "irradiance": [1, 1, 1]},
        {"type": "environment", "file": "sky.pfm", "scale": 2, "rotate": {"axis": [0, 1, 0], "degrees": 90}},
        {"type": "spot", "position": [1, 0.9, 0], "direction": [0, -1, 0]}])");
    const Scene scene = load_scene(path, testing::full_registry());
    CHECK(scene.warnings.empty());
    // Two emissive triangles first (in mesh order), then the array in its order.
    REQUIRE(scene.lights.size() == 7u);
    for (std::size_t i = 0; i < scene.lights.size(); ++i) CHECK(scene.lights[i]->index == i);
    CHECK(scene.lights[0]->type() == LightType::Area);
    CHECK(scene.lights[1]->type() == LightType::Area);
    CHECK(scene.lights[0]->where == "mesh 'lamp', triangle 0");
    CHECK(scene.lights[1]->where == "mesh 'lamp', triangle 1");
    CHECK(scene.lights[2]->type() == LightType::DeltaPosition);
    CHECK(scene.lights[3]->type() == LightType::DeltaPosition);
    CHECK(scene.lights[4]->type() == LightType::DeltaDirection);
    CHECK(scene.lights[5]->type() == LightType::Infinite);
    CHECK(scene.lights[6]->type() == LightType::DeltaPosition);
    for (std::size_t i = 2; i < 7; ++i) CHECK(scene.lights[i]->where == path + ": /lights/" + std::to_string(i - 2));
    CHECK(scene.environment == scene.lights[5].get());
    // What was read: the point light's intensity, the environment's scaled radiance.
    const auto point = scene.lights[2]->sample_li(Vec3(0.0f, 0.5f, 2.0f), Vec2(0.5f));
    REQUIRE(point);
    CHECK(point->radiance.b == Approx(3.0f / 4.0f));
    CHECK(scene.environment->le(Vec3(0.0f, -1.0f, 0.0f)).g == Approx(1.0f));  // 2 x 0.5, the bottom row
    // Preprocessed with the scene's bounds: the directional light's power is E pi r^2.
    const float radius = 0.5f * glm::length(scene.bounds.diagonal());
    CHECK(scene.lights[4]->power().r == Approx(Pi * radius * radius));
}

TEST_CASE("a constant environment loads, and a scene without lights has only its area lights", "[unit][scene][ch03]") {
    TemporaryFolder folder;
    const Scene constant = load_scene(make_scene(folder, R"([{"type": "constant", "radiance": 0.25}])"), testing::full_registry());
    REQUIRE(constant.environment != nullptr);
    CHECK(constant.environment->le(Vec3(0.0f, 0.0f, 1.0f)) == Spectrum(0.25f));
    CHECK(constant.environment->index == 2u);
    const Scene plain = load_scene(make_scene(folder, ""), testing::full_registry());
    CHECK(plain.lights.size() == 2u);
    CHECK(plain.environment == nullptr);
}

TEST_CASE("every emissive triangle has an area light, and a hit maps back to it", "[unit][scene][ch03]") {
    TemporaryFolder folder;
    const Scene scene = load_scene(make_scene(folder, ""), testing::full_registry());
    REQUIRE(scene.emissive_triangles.size() == 2u);
    REQUIRE(scene.lights.size() == 2u);
    // Straight up from the floor into each lamp triangle: (0.75, 0.25) is in the first
    // (4 5 6), (0.25, 0.75) in the second (4 6 7).
    for (const auto& [x, z, light] : {std::tuple{0.75f, 0.25f, 0u}, std::tuple{0.25f, 0.75f, 1u}}) {
        const auto hit = scene.intersect(Ray{Vec3(x, 0.5f, z), Vec3(0.0f, 1.0f, 0.0f)});
        REQUIRE(hit);
        INFO("ray up at (" << x << ", " << z << ")");
        CHECK(scene.area_light(*hit) == scene.lights[light].get());
        // The area light is the triangle that was hit: its density towards the hit point is
        // positive from below (the lamp faces down) and its power is pi A Le = pi 0.5 4.
        CHECK(scene.area_light(*hit)->pdf_li(Vec3(x, 0.5f, z), Vec3(0.0f, 1.0f, 0.0f)) > 0.0f);
        CHECK(scene.area_light(*hit)->power().r == Approx(Pi * 0.5f * 4.0f));
    }
    // The floor does not emit.
    const auto floor = scene.intersect(Ray{Vec3(0.0f, 0.5f, 0.0f), Vec3(0.0f, -1.0f, 0.0f)});
    REQUIRE(floor);
    CHECK(scene.area_light(*floor) == nullptr);
}

TEST_CASE("light errors name the JSON path or the file", "[unit][scene][ch03]") {
    TemporaryFolder folder;
    SECTION("an unknown type, with the nearest name") {
        const std::string message = testing::scene_load_error(make_scene(folder, R"([{"type": "spott", "position": [0, 1, 0]}])"));
        CHECK_THAT(message, Catch::Contains("/lights/0/type") && Catch::Contains("unknown light 'spott'") &&
                                Catch::Contains("did you mean 'spot'"));
    }
    SECTION("type area is refused: area lights come from emissive materials") {
        const std::string message = testing::scene_load_error(make_scene(folder, R"([{"type": "constant"}, {"type": "area"}])"));
        CHECK_THAT(message, Catch::Contains("/lights/1/type") && Catch::Contains("emissive materials"));
    }
    SECTION("two environments are refused, naming the first") {
        const std::string message = testing::scene_load_error(make_scene(folder, R"([{"type": "constant"}, {"type": "point", "position": [0, 0, 0]},
            {"type": "environment", "file": "sky.pfm"}])"));
        CHECK_THAT(message, Catch::Contains("/lights/2/type") && Catch::Contains("at most one environment") &&
                                Catch::Contains("/lights/0"));
    }
    SECTION("an environment map with a negative or NaN pixel is refused, naming the file and the pixel") {
        for (const float bad : {-1.0f, std::numeric_limits<float>::quiet_NaN()}) {
            Image image(4, 2, Spectrum(1.0f));
            image.at(3, 1).g = bad;
            write_image(folder.file("bad.pfm"), image);
            const std::string message = testing::scene_load_error(make_scene(folder, R"([{"type": "environment", "file": "bad.pfm"}])"));
            INFO("pixel value " << bad);
            CHECK_THAT(message, Catch::Contains("bad.pfm") && Catch::Contains("pixel (3, 1)") &&
                                    Catch::Contains("negative or not finite"));
        }
    }
    SECTION("a missing environment file names the path") {
        const std::string message = testing::scene_load_error(make_scene(folder, R"([{"type": "environment", "file": "nowhere.exr"}])"));
        CHECK_THAT(message, Catch::Contains("/lights/0/file") && Catch::Contains("nowhere.exr"));
    }
    SECTION("a spot with both look_at and direction") {
        const std::string message = testing::scene_load_error(make_scene(folder, R"([{"type": "spot", "position": [0, 1, 0],
            "look_at": [0, 0, 0], "direction": [0, -1, 0]}])"));
        CHECK_THAT(message, Catch::Contains("/lights/0/direction") && Catch::Contains("not both"));
    }
    SECTION("zero directions: spot, directional, spot looking at itself, rotation axis") {
        CHECK_THAT(testing::scene_load_error(make_scene(folder, R"([{"type": "spot", "position": [0, 1, 0], "direction": [0, 0, 0]}])")),
                   Catch::Contains("/lights/0/direction"));
        CHECK_THAT(testing::scene_load_error(make_scene(folder, R"([{"type": "directional", "direction": [0, 0, 0]}])")),
                   Catch::Contains("/lights/0/direction"));
        CHECK_THAT(testing::scene_load_error(make_scene(folder, R"([{"type": "spot", "position": [0, 1, 0], "look_at": [0, 1, 0]}])")),
                   Catch::Contains("/lights/0/look_at"));
        CHECK_THAT(testing::scene_load_error(make_scene(folder, R"([{"type": "environment", "file": "sky.pfm",
            "rotate": {"axis": [0, 0, 0], "degrees": 10}}])")),
                   Catch::Contains("/lights/0/rotate/axis"));
    }
    SECTION("out-of-range values and missing keys") {
        CHECK_THAT(testing::scene_load_error(make_scene(folder, R"([{"type": "point", "position": [0, 1, 0], "intensity": -1}])")),
                   Catch::Contains("/lights/0/intensity"));
        CHECK_THAT(testing::scene_load_error(make_scene(folder, R"([{"type": "point"}])")), Catch::Contains("/lights/0/position"));
        CHECK_THAT(testing::scene_load_error(make_scene(folder, R"([{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0],
            "cone_angle_degrees": 20, "falloff_start_degrees": 30}])")),
                   Catch::Contains("/lights/0/falloff_start_degrees"));
        CHECK_THAT(testing::scene_load_error(make_scene(folder, R"({"type": "point"})")), Catch::Contains("/lights") &&
                                                                             Catch::Contains("array"));
    }
}

TEST_CASE("a chapter-02 renderer refuses a point light: introduced in chapter 03", "[unit][scene][ch03]") {
    Registry chapter02("ch02", 2);
    register_chapter02(chapter02);
    TemporaryFolder folder;
    const std::string path = make_scene(folder, R"([{"type": "point", "position": [0, 0.5, 0]}])");
    CHECK_THAT(testing::scene_load_error(path, chapter02), Catch::Contains("/lights/0/type") && Catch::Contains("introduced in chapter 03"));
    // Without the lights array the same renderer loads the scene; its lamp is still emissive
    // (chapters 01 and 02 find it by hitting it) but no area light is made.
    const Scene scene = load_scene(make_scene(folder, ""), chapter02);
    CHECK(scene.emissive_triangles.size() == 2u);
    CHECK(scene.lights.empty());
    const auto hit = scene.intersect(Ray{Vec3(0.75f, 0.5f, 0.25f), Vec3(0.0f, 1.0f, 0.0f)});
    REQUIRE(hit);
    CHECK(scene.area_light(*hit) == nullptr);
}
