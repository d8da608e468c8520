// The registry's names and its messages for capabilities of later chapters.
#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/complete_renderer.hpp"
#include "freezeray/course_catalogue.hpp"
#include "freezeray/error.hpp"
#include "freezeray/options.hpp"
#include "freezeray/registry.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <set>

using namespace freezeray;

TEST_CASE("a name from a later chapter is refused with the chapter that introduces it", "[unit][registry]") {
    Registry registry("ch01", 1);
    register_chapter01(registry);
    try {
        registry.integrators.make("pt-mis", "--integrator", RenderSettings{}, Parameters::none());
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("--integrator") && Catch::Contains("introduced in chapter 03") &&
                                 Catch::Contains("ch01"));
    }
}

TEST_CASE("an unknown name is refused with the nearest registered name", "[unit][registry]") {
    const Registry& registry = testing::full_registry();
    try {
        registry.integrators.make("pt-naiv", "--integrator", RenderSettings{}, Parameters::none());
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("did you mean 'pt-naive'"));
    }
    CHECK(registry.has(CapabilityKind::Integrator, "pt-naive"));
    CHECK(registry.has(CapabilityKind::Material, "diffuse"));
    CHECK(registry.has(CapabilityKind::Accelerator, "bruteforce"));
}

TEST_CASE("nearest_name picks the closest by edit distance", "[unit][registry]") {
    CHECK(nearest_name("sdp", {"seed", "spp_max", "sp"}) == "sp");
    CHECK(nearest_name("spp", {"seed", "spp_max", "sp"}) == "spp_max");
    CHECK(nearest_name("fov", {"fov_vertical_degrees", "position"}) == "fov_vertical_degrees");
}

TEST_CASE("the course catalogue lists exactly what the complete renderer registers, each with its chapter",
          "[unit][registry]") {
    const Registry& registry = testing::full_registry();
    std::set<std::pair<CapabilityKind, std::string>> catalogued;
    for (const CatalogueEntry& entry : course_catalogue()) {
        INFO(capability_kind_name(entry.kind) << " '" << entry.name << "' (chapter " << entry.chapter << ")");
        CHECK(catalogued.insert({entry.kind, entry.name}).second);  // listed once
        // Every catalogued capability of a chapter this build has is registered...
        if (chapter_is_written(entry.chapter)) CHECK(registry.has(entry.kind, entry.name));
        if (!chapter_is_written(entry.chapter)) CHECK_FALSE(registry.has(entry.kind, entry.name));
    }
    // ... and every registered one is catalogued, with the chapter that registered it.
    for (CapabilityKind kind : all_capability_kinds)
        for (const Registry::Entry& entry : registry.list(kind)) {
            INFO(capability_kind_name(kind) << " '" << entry.name << "' introduced by chapter " << entry.introduced_in);
            CHECK(registry.chapter_introducing(kind, entry.name) == entry.introduced_in);
        }
    CHECK(registry.chapter() == last_chapter());
}

TEST_CASE("a chapter's option reaches its integrator from the scene and the command line, which wins",
          "[unit][registry][options]") {
    const Registry& registry = testing::full_registry();
    const nlohmann::json block = {{"mlt_sigma", 0.05}, {"mlt_chains", 64}};
    OptionValues given;
    given.values["mlt_chains"] = 32;
    given.flags["mlt_chains"] = "--mlt-chains";
    const OptionParameters options(&block, "scene.json", "/render", ".", given, registry.options(),
                                   OptionTarget::Integrator);
    const Parameters& p = options.parameters();
    CHECK(p.get_float("mlt_sigma", 0.0f) == 0.05f);
    CHECK(p.get_int("mlt_chains", 0) == 32);
    CHECK(p.where("mlt_chains") == "--mlt-chains");
    CHECK(p.where("mlt_sigma") == "scene.json: /render/mlt_sigma");
    // An option of another integrator is refused, one of this integrator's is not.
    CHECK_THROWS_WITH(check_options_apply(given, registry.options(), OptionTarget::Integrator, "pt-mis"),
                      Catch::Contains("--mlt-chains") && Catch::Contains("not of pt-mis"));
    CHECK_NOTHROW(check_options_apply(given, registry.options(), OptionTarget::Integrator, "mlt-multiplexed"));
}

TEST_CASE("every declared option has a flag, a key and a chapter this renderer has, each once", "[unit][registry][options]") {
    const Registry& registry = testing::full_registry();
    std::set<std::string> flags;
    for (const OptionDeclaration& d : registry.options()) {
        INFO(d.flag);
        CHECK(d.flag.rfind("--", 0) == 0);
        CHECK(!d.key.empty());
        CHECK(d.chapter >= 1);
        CHECK(d.chapter <= registry.chapter());
        CHECK(flags.insert(d.flag).second);
        for (const std::string& user : d.used_by)
            CHECK(registry.has(d.target == OptionTarget::Integrator    ? CapabilityKind::Integrator
                               : d.target == OptionTarget::Accelerator ? CapabilityKind::Accelerator
                                                                       : CapabilityKind::TextureLayout,
                               user));
    }
    Registry copy("test", 1);
    copy.add_option({"--x", "x", OptionType::Number, OptionTarget::Integrator, "x", {}, 1});
    CHECK_THROWS(copy.add_option({"--x", "y", OptionType::Number, OptionTarget::Integrator, "y", {}, 1}));
}

TEST_CASE("the accelerator comes from the command line, else the scene's block, else the default", "[unit][registry]") {
    const Registry& registry = testing::full_registry();
    const std::string scene = testing::scene_path("cornell-box/scene.json");
    CHECK(load_scene(scene, registry).accelerator_name == registry.accelerators.default_name());
    SceneLoadOptions options;
    options.selections[CapabilityKind::Accelerator] = "bruteforce";
    CHECK(load_scene(scene, registry, options).accelerator_name == "bruteforce");
    options.selections[CapabilityKind::Accelerator] = "octree";
    CHECK_THROWS_WITH(load_scene(scene, registry, options), Catch::Contains("--accel") && Catch::Contains("octree"));
}
