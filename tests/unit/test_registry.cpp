// The registry's names and its messages for capabilities of later chapters.
#include "freezeray/error.hpp"
#include "freezeray/registry.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;

TEST_CASE("a name from a later chapter is refused with the chapter that introduces it", "[unit][registry]") {
    const Registry registry("ch01", 1);
    try {
        registry.make_integrator("pt-mis", RenderSettings{}, "--integrator");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("--integrator") && Catch::Contains("introduced in chapter 03") &&
                                 Catch::Contains("ch01"));
    }
}

TEST_CASE("an unknown name is refused with the nearest registered name", "[unit][registry]") {
    const Registry& registry = testing::full_registry();
    try {
        registry.make_integrator("pt-naiv", RenderSettings{}, "--integrator");
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
