// Loading JSON scenes: the shipped scenes, overrides, effects, and errors that name the place.
#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/error.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <optional>

using namespace freezeray;
using freezeray::testing::TemporaryFolder;

namespace {

// A one-triangle OBJ with one material, and a scene around it; `scene_text` may refer to
// tri.obj.
std::string make_scene(const TemporaryFolder& folder, const std::string& scene_text) {
    folder.write("tri.mtl", "newmtl paint\nKd 0.5 0.25 0.125\n\nnewmtl lamp\nKd 0 0 0\nKe 2 2 2\n");
    folder.write("tri.obj", "mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl paint\nf 1 2 3\n"
                                       "usemtl lamp\nf 1 3 4\n");
    folder.write("scene.json", scene_text);
    return folder.file("scene.json");
}

const std::string camera = R"("camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov_vertical_degrees": 40, "resolution": [8, 4]})";

}  // namespace

TEST_CASE("the Cornell box loads with its published dimensions, materials and light", "[unit][scene]") {
    const Scene scene = load_scene(testing::scene_path("cornell-box/scene.json"), testing::full_registry());
    CHECK(scene.triangle_count() == 32u);  // 16 quads
    CHECK(scene.emissive_triangles.size() == 2u);
    CHECK(scene.camera_description.position == Vec3(278, 273, -800));
    CHECK(scene.camera_description.fov_vertical_degrees == Approx(39.3f));
    CHECK(scene.bounds.max.x == Approx(556.0f));
    CHECK(scene.bounds.max.z == Approx(559.2f));
    CHECK(scene.effects.area_emitters);
    CHECK(scene.effects.diffuse);
    CHECK_FALSE(scene.effects.specular);
    CHECK_FALSE(scene.effects.transmission);
    CHECK(scene.warnings.empty());
    // The light faces down.
    const auto& light = scene.emissive_triangles[0];
    const TriangleMesh& mesh = scene.meshes[light.mesh];
    const auto& t = mesh.triangles[light.triangle];
    const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    CHECK(n.y < 0.0f);
}

TEST_CASE("materials come from the MTL and JSON overrides replace them by name", "[unit][scene]") {
    TemporaryFolder folder;
    const std::string path = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj", "transform": {"translate": [1, 2, 3], "scale": 2}}],
        "materials": {"lamp": {"emission": [5, 6, 7]}}})");
    const Scene scene = load_scene(path, testing::full_registry());
    REQUIRE(scene.materials.size() == 2u);
    CHECK(scene.materials[0]->name == "paint");
    CHECK(scene.materials[0]->type == "diffuse");
    CHECK(scene.materials[1]->emission == Spectrum(5, 6, 7));
    CHECK(scene.emissive_triangles.size() == 1u);
    CHECK(scene.bounds.min == Vec3(1, 2, 3));
    CHECK(scene.bounds.max == Vec3(3, 4, 5));
    CHECK(scene.camera_description.width == 8);
    CHECK(scene.camera_description.height == 4);
}

TEST_CASE("scene errors name the file and the JSON path or line", "[unit][scene]") {
    TemporaryFolder folder;
    SECTION("malformed JSON gives line and column") {
        const std::string path = make_scene(folder, "{\n  \"camera\": {,\n}");
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("scene.json:2:") && Catch::Contains("malformed JSON"));
    }
    SECTION("a missing OBJ names the JSON path and the file") {
        const std::string path = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "nowhere.obj"}]})");
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/meshes/0/file") && Catch::Contains("nowhere.obj"));
    }
    SECTION("an unknown material type names the path and the chapter introducing it") {
        const std::string path = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj"}],
            "materials": {"paint": {"type": "roughconductor"}}})");
        Registry chapter01("ch01", 1);
        register_chapter01(chapter01);
        CHECK_THAT(testing::scene_load_error(path, chapter01), Catch::Contains("/materials/paint/type") && Catch::Contains("chapter 02"));
        const std::string path2 = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj"}],
            "materials": {"paint": {"type": "velvet"}}})");
        CHECK_THAT(testing::scene_load_error(path2), Catch::Contains("unknown material 'velvet'"));
    }
    SECTION("wrong types and out-of-range values name the path") {
        const std::string path = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj"}],
            "materials": {"paint": {"albedo": "red"}}})");
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/materials/paint/albedo") && Catch::Contains("expected"));
        const std::string path2 = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj"}],
            "materials": {"paint": {"albedo": [0.5, 1.5, 0.5]}}})");
        CHECK_THAT(testing::scene_load_error(path2), Catch::Contains("/materials/paint/albedo") && Catch::Contains("outside"));
    }
    SECTION("a missing camera, and a camera looking at itself") {
        const std::string path = make_scene(folder, R"({"meshes": [{"file": "tri.obj"}]})");
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/camera"));
        const std::string path2 = make_scene(folder, R"({"camera": {"position": [1, 1, 1], "look_at": [1, 1, 1], "fov_vertical_degrees": 40}, "meshes": [{"file": "tri.obj"}]})");
        CHECK_THAT(testing::scene_load_error(path2), Catch::Contains("/camera/look_at"));
    }
    SECTION("an absurd resolution is refused before anything is allocated") {
        const std::string path = make_scene(folder, R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov_vertical_degrees": 40, "resolution": [100000, 100000]}, "meshes": [{"file": "tri.obj"}]})");
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/camera/resolution"));
    }
}

TEST_CASE("unknown keys give a warning with the nearest valid name", "[unit][scene]") {
    TemporaryFolder folder;
    const std::string path = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj"}], "rendr": {}})");
    const Scene scene = load_scene(path, testing::full_registry());
    REQUIRE(scene.warnings.size() == 1u);
    CHECK_THAT(scene.warnings[0], Catch::Contains("'rendr'") && Catch::Contains("did you mean 'render'"));
}

TEST_CASE("a wrong JSON type at any level names its path", "[unit][scene]") {
    TemporaryFolder folder;
    const std::string good_camera = R"({"position": [0, 0, 5], "look_at": [0, 0, 0], "fov_vertical_degrees": 40})";
    // Each case: the scene text and the JSON path its message must name.
    const std::pair<std::string, std::string> cases[] = {
        {R"([1, 2, 3])", "scene.json: /"},
        {R"({"camera": [0, 0, 5], "meshes": [{"file": "tri.obj"}]})", "/camera"},
        {R"({"camera": )" + good_camera + R"(, "meshes": {"file": "tri.obj"}})", "/meshes"},
        {R"({"camera": )" + good_camera + R"(, "meshes": ["tri.obj"]})", "/meshes/0"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": 7}]})", "/meshes/0/file"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj", "transform": "identity"}]})",
         "/meshes/0/transform"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj", "transform": {"rotate": 30}}]})",
         "/meshes/0/transform/rotate"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj", "transform": {"scale": "big"}}]})",
         "/meshes/0/transform/scale"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj", "transform": {"matrix": [1, 0]}}]})",
         "/meshes/0/transform/matrix"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj", "material": 3}]})", "/meshes/0/material"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj"}], "materials": []})", "/materials"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj"}], "materials": {"paint": 0.5}})",
         "/materials/paint"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj"}], "materials": {"paint": {"type": 2}}})",
         "/materials/paint/type"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj"}], "render": [16]})", "/render"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj"}], "render": {"spp": 1.5}})",
         "/render/spp"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj"}], "render": {"integrator": false}})",
         "/render/integrator"},
        {R"({"camera": )" + good_camera + R"(, "meshes": [{"file": "tri.obj"}], "chapter": "two"})", "/chapter"},
        {R"({"camera": {"position": "here", "look_at": [0, 0, 0], "fov_vertical_degrees": 40}, "meshes": [{"file": "tri.obj"}]})",
         "/camera/position"},
        {R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov_vertical_degrees": [40]}, "meshes": [{"file": "tri.obj"}]})",
         "/camera/fov_vertical_degrees"},
        {R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov_vertical_degrees": 40, "resolution": "hd"}, "meshes": [{"file": "tri.obj"}]})",
         "/camera/resolution"},
    };
    for (const auto& [text, where] : cases) {
        INFO(text);
        CHECK_THAT(testing::scene_load_error(make_scene(folder, text)), Catch::Contains(where) && Catch::Contains("scene.json"));
    }
}

TEST_CASE("numbers beyond single precision and impossible frames are refused with their path", "[unit][scene]") {
    TemporaryFolder folder;
    const std::string mesh = R"(, "meshes": [{"file": "tri.obj"}]})";
    SECTION("a number beyond double precision is malformed JSON at its line and column") {
        const std::string path = make_scene(folder, "{\n  \"camera\": {\"position\": [0, 0, 1e400]," + mesh);
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("scene.json:2:33") && Catch::Contains("1e400"));
    }
    SECTION("a camera whose view direction overflows") {
        const std::string path = make_scene(folder, R"({"camera": {"position": [3e38, 0, 0], "look_at": [-3e38, 0, 0], "fov_vertical_degrees": 40})" + mesh);
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/camera/look_at"));
    }
    SECTION("a zero up vector") {
        const std::string path = make_scene(folder, R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 0, 0], "fov_vertical_degrees": 40})" + mesh);
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/camera/up"));
    }
    SECTION("a matrix entry too large for a float") {
        const std::string path = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj", "transform": {"matrix": [1e39,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}}]})");
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/meshes/0/transform/matrix/0") && Catch::Contains("single precision"));
    }
    SECTION("a matrix together with translate") {
        const std::string path = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj", "transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "translate": [1, 2, 3]}}]})");
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/meshes/0/transform/translate") && Catch::Contains("matrix"));
    }
    SECTION("a transform that cannot be inverted names the mesh's JSON path") {
        const std::string path = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj", "transform": {"scale": [1e30, 1e30, 1e30]}}]})");
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/meshes/0/transform"));
    }
    SECTION("a transform that moves the mesh beyond single precision") {
        const std::string path = make_scene(folder, "{" + camera + R"(, "meshes": [{"file": "tri.obj", "transform": {"translate": [3e38, 0, 0], "scale": [1e38, 1, 1]}}]})");
        CHECK_THAT(testing::scene_load_error(path), Catch::Contains("/meshes/0/transform"));
    }
}

TEST_CASE("unknown keys of the camera and of a transform give warnings with the nearest name", "[unit][scene]") {
    TemporaryFolder folder;
    const std::string path = make_scene(folder, R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov_vertical_degrees": 40, "resolutoin": [8, 8]},
        "meshes": [{"file": "tri.obj", "transform": {"translation": [1, 0, 0]}}]})");
    const Scene scene = load_scene(path, testing::full_registry());
    REQUIRE(scene.warnings.size() == 2u);
    CHECK_THAT(scene.warnings[0], Catch::Contains("/camera/resolutoin") && Catch::Contains("did you mean 'resolution'"));
    CHECK_THAT(scene.warnings[1], Catch::Contains("/meshes/0/transform/translation") &&
                                      Catch::Contains("did you mean 'translate'"));
}

// What `info` lists as the render's work per ray follows the scene: the Cornell box calls for
// none of it, the environment-lit spheres (a sky, a checkered floor) for the environment and the
// texels; the flags it reads are the ones Scene::intersect, occluded and environment_radiance test.
TEST_CASE("the work per ray that info lists is what the scene calls for", "[unit][scene]") {
    const Scene cornell = load_scene(testing::scene_path("cornell-box/scene.json"), testing::full_registry());
    CHECK(cornell.environment == nullptr);
    CHECK_FALSE(cornell.has_alpha_masks);
    CHECK(cornell.texture_footprint == nullptr);
    const std::string cornell_work = describe_work_per_ray(cornell);
    CHECK(cornell_work.find("[x]") == std::string::npos);
    CHECK_THAT(cornell_work, Catch::Contains("[ ] environment lookup") && Catch::Contains("[ ] alpha-mask test") &&
                                 Catch::Contains("[ ] texel reads") && Catch::Contains("nothing is textured"));

    const Scene spheres = load_scene(testing::scene_path("material-spheres/scene-environment.json"), testing::full_registry());
    REQUIRE(spheres.environment != nullptr);
    REQUIRE(spheres.effects.textures);
    const std::string spheres_work = describe_work_per_ray(spheres);
    CHECK_THAT(spheres_work, Catch::Contains("[x] environment lookup") && Catch::Contains("[x] texel reads") &&
                                 Catch::Contains("[ ] alpha-mask test"));
}

// The scenes that read the shared large scenes (scenes/sponza): what their files promise.
TEST_CASE("Sponza loads under its white sky, at night with its lanterns and night sky, and by day", "[unit][scene]") {
    const std::optional<std::string> shared = testing::shared_scenes_folder();
    if (!shared || !std::filesystem::exists(*shared + "/crytek-sponza/sponza.obj") ||
        !std::filesystem::exists(*shared + "/envmaps/dikhololo_night_1k.hdr")) {
        WARN("skipped: the shared Sponza or its night sky is not there (set FREEZERAY_SHARED_SCENES)");
        return;
    }
    SceneLoadOptions options;
    options.selections[CapabilityKind::Accelerator] = "bruteforce";  // what is loaded is the question here, not the tree
    constexpr std::size_t SponzaTriangles = 262266;  // 262,267 in the file, one of zero area dropped
    SECTION("under the white sky: the constant environment, nothing that emits") {
        const Scene scene = load_scene(testing::scene_path("sponza/scene.json"), testing::full_registry(), options);
        CHECK(scene.triangle_count() == SponzaTriangles);
        CHECK(scene.emissive_triangles.empty());
        REQUIRE(scene.lights.size() == 1u);
        CHECK(scene.environment == scene.lights[0].get());
        CHECK(scene.effects.textures);
    }
    SECTION("at night: eighteen lanterns of 80 emissive triangles and the night sky") {
        const Scene scene = load_scene(testing::scene_path("sponza/night.json"), testing::full_registry(), options);
        CHECK(scene.triangle_count() == SponzaTriangles + 18 * 80);
        CHECK(scene.emissive_triangles.size() == 18u * 80u);
        CHECK(scene.lights.size() == 18u * 80u + 1u);  // one area light per emissive triangle, then the sky
        CHECK(scene.environment != nullptr);
        CHECK(scene.effects.area_emitters);
        CHECK(scene.effects.environment);
        // The lanterns hang in the open, inside Sponza's bounds.
        for (const auto& emitter : scene.emissive_triangles) {
            const TriangleMesh& mesh = scene.meshes[emitter.mesh];
            const Vec3 p = mesh.positions[mesh.triangles[emitter.triangle][0]];
            CHECK((p.y > 200.0f && p.y < 400.0f));
        }
    }
    SECTION("by day: the daylight map alone, nothing that emits") {
        if (!std::filesystem::exists(*shared + "/envmaps/rooitou_park_1k.hdr")) {
            WARN("skipped: the shared daylight map is not there");
            return;
        }
        const Scene scene = load_scene(testing::scene_path("sponza/day.json"), testing::full_registry(), options);
        CHECK(scene.triangle_count() == SponzaTriangles);
        CHECK(scene.emissive_triangles.empty());
        REQUIRE(scene.lights.size() == 1u);
        CHECK(scene.environment == scene.lights[0].get());
        CHECK(scene.effects.environment);
        CHECK_FALSE(scene.effects.area_emitters);
    }
}

// Bitterli's scenes (scenes/staircase2, veach-bidir, water-caustic, material-testball): the
// meshes, emitters and cameras their shared files describe (../shared/scenes/*/camera.txt,
// lights.txt, SOURCE.txt).
TEST_CASE("Bitterli's scenes load with the cameras and lights of their originals", "[unit][scene]") {
    const std::optional<std::string> shared = testing::shared_scenes_folder();
    if (!shared || !std::filesystem::exists(*shared + "/staircase2/staircase2.obj")) {
        WARN("skipped: the shared Bitterli scenes are not there (set FREEZERAY_SHARED_SCENES)");
        return;
    }
    SceneLoadOptions options;
    options.selections[CapabilityKind::Accelerator] = "bruteforce";
    struct Expected {
        const char* scene;
        std::size_t triangles, emissive;  // triangles after the loader drops the degenerate ones
        int width, height;
        Spectrum brightest;  // the largest radiance of lights.txt
        bool environment;
    };
    const Expected cases[] = {
        // 31,407 triangles, 2,432 of zero area; 5 disks of 96 triangles and 8 rectangles of 2.
        {"staircase2/scene.json", 28975, 5 * 96 + 8 * 2, 640, 360, Spectrum(4.575f, 3.59076f, 1.54977f), false},
        {"veach-bidir/scene.json", 11544, 2 * 2, 512, 512, Spectrum(12048.2f, 8605.84f, 6196.21f), false},
        {"water-caustic/scene.json", 103487, 2, 512, 512, Spectrum(541127.0f, 381972.0f, 127324.0f), false},
        // 80,770 triangles, 128 of zero area; lit by the environment alone.
        {"material-testball/scene.json", 80642, 0, 640, 360, Spectrum(0.0f), true},
    };
    for (const Expected& e : cases) {
        INFO(e.scene);
        const Scene scene = load_scene(testing::scene_path(e.scene), testing::full_registry(), options);
        CHECK(scene.triangle_count() == e.triangles);
        CHECK(scene.emissive_triangles.size() == e.emissive);
        CHECK(scene.camera->width() == e.width);
        CHECK(scene.camera->height() == e.height);
        CHECK((scene.environment != nullptr) == e.environment);
        Spectrum brightest(0.0f);
        for (const auto& m : scene.materials)
            if (m->is_emissive() && max_component(m->emission) > max_component(brightest)) brightest = m->emission;
        CHECK(brightest.r == e.brightest.r);
        CHECK(brightest.g == e.brightest.g);
        CHECK(brightest.b == e.brightest.b);
    }
}
