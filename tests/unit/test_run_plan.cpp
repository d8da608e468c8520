// The run plan (application/run_plan.hpp) and the scene's description apart from its building
// (scene-input/): one rule for every kind's choice, the chapters' options on every command, and a
// scene made of a description that no file gave.
#include "freezeray/comparison.hpp"
#include "freezeray/error.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/run_plan.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/scene_readers.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;
using freezeray::testing::full_registry;
using freezeray::testing::TemporaryFolder;

namespace {

std::string error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

const Scene& cornell() {
    static const Scene scene = [] {
        SceneLoadOptions options;
        options.width = 16;
        options.height = 16;
        return load_scene(testing::scene_path("cornell-box/scene.json"), full_registry(), options);
    }();
    return scene;
}

}  // namespace

TEST_CASE("a run's kinds come from its own name, else the selectors, else the scene, else the default", "[unit][run-plan]") {
    const Registry& registry = full_registry();
    RunRequest request;
    request.run = "pt-mis";
    RunPlan plan = plan_run(request, cornell(), registry);
    CHECK(plan.sampler_name == registry.samplers.default_name());
    CHECK(plan.light_sampler_name == registry.light_samplers.default_name());

    request.selections[CapabilityKind::Sampler] = "independent";
    request.selections[CapabilityKind::LightSampler] = "uniform";
    plan = plan_run(request, cornell(), registry);
    CHECK(plan.sampler_name == "independent");
    CHECK(plan.light_sampler_name == "uniform");

    request.run = "pt-mis@sobol@power";  // the run's own names win over the selectors
    plan = plan_run(request, cornell(), registry);
    CHECK(plan.name == "pt-mis@sobol@power");
    CHECK(plan.integrator_name == "pt-mis");
    CHECK(plan.sampler_name == "sobol");
    CHECK(plan.light_sampler_name == "power");
    CHECK(plan.settings.sampler != nullptr);
    CHECK(plan.settings.light_sampler != nullptr);
}

TEST_CASE("a run's choices are checked against what its integrator is", "[unit][run-plan]") {
    const Registry& registry = full_registry();
    RunRequest request;
    request.run = "light-tracing";
    // Light tracing draws from its own streams and chooses no light per point: without names it
    // gets the independent sampler and no light sampler; named ones are refused where they were named.
    const RunPlan plan = plan_run(request, cornell(), registry);
    CHECK(plan.sampler_name == "independent");
    CHECK(plan.light_sampler_name.empty());
    request.selections[CapabilityKind::Sampler] = "sobol";
    CHECK_THAT(error_of([&] { plan_run(request, cornell(), registry); }), Catch::StartsWith("--sampler: light-tracing draws"));
    request.selections.clear();
    request.run = "light-tracing@bvh";
    request.where = "--integrators";
    CHECK_THAT(error_of([&] { plan_run(request, cornell(), registry); }),
               Catch::StartsWith("--integrators: light-tracing does not choose lights"));
    request.run = "pt-mis@sobol@zsobol";
    CHECK_THAT(error_of([&] { plan_run(request, cornell(), registry); }), Catch::Contains("a run names at most one of each"));
    request.run = "pt-mis@sobbol";
    CHECK_THAT(error_of([&] { plan_run(request, cornell(), registry); }), Catch::Contains("sobol"));
}

TEST_CASE("the budget: the given samples, else none when time or an error target decides, else the scene's", "[unit][run-plan]") {
    const Registry& registry = full_registry();
    RunRequest request;
    request.run = "pt-nee";
    CHECK(plan_run(request, cornell(), registry).settings.samples_per_pixel == cornell().defaults.samples_per_pixel);
    request.time_seconds = 1.0;
    CHECK(plan_run(request, cornell(), registry).settings.samples_per_pixel == UINT64_MAX);
    request.samples_per_pixel = 7;
    CHECK(plan_run(request, cornell(), registry).settings.samples_per_pixel == 7);
    CHECK(plan_run(request, cornell(), registry).settings.seed == cornell().defaults.seed);
    request.seed = 42;
    request.max_depth = 3;
    const RunPlan plan = plan_run(request, cornell(), registry);
    CHECK(plan.settings.seed == 42);
    CHECK(plan.settings.max_depth == 3);
}

TEST_CASE("a chapter's option must be read by one of the runs, and each run's integrator reads its own", "[unit][run-plan]") {
    const Registry& registry = full_registry();
    std::vector<RunRequest> requests(2);
    requests[0].run = "pt-mis";
    requests[1].run = "mlt";
    for (RunRequest& r : requests) {
        r.where = "--integrators";
        r.options.values["mlt_chains"] = 10;
        r.options.flags["mlt_chains"] = "--mlt-chains";
    }
    CHECK(plan_runs(requests, cornell(), registry).size() == 2);  // mlt reads it; pt-mis passes it by
    requests.pop_back();
    CHECK_THAT(error_of([&] { plan_runs(requests, cornell(), registry); }),
               Catch::StartsWith("--mlt-chains: is an option of mlt"));
}

TEST_CASE("compare takes the scene's selectors and the chapters' options", "[unit][run-plan][compare]") {
    TemporaryFolder folder;
    CompareRequest request;
    request.scene = testing::scene_path("cornell-box/scene.json");
    request.integrators = {"pt-nee", "mlt"};
    request.samples_per_pixel = 1;
    request.width = request.height = 8;
    request.quiet = true;
    request.out_folder = folder.file("report");
    request.selections[CapabilityKind::Accelerator] = "bruteforce";
    request.options.values["mlt_chains"] = 5;
    request.options.flags["mlt_chains"] = "--mlt-chains";
    const Comparison comparison = run_comparison(request, full_registry());
    CHECK(comparison.runs.size() == 2);
    request.selections[CapabilityKind::Accelerator] = "octree";
    CHECK_THAT(error_of([&] { run_comparison(request, full_registry()); }), Catch::StartsWith("--accel:"));
}

TEST_CASE("a scene file is read by the reader of its extension", "[unit][scene-input]") {
    TemporaryFolder folder;
    const std::string path = folder.write("scene.pbrt", "Camera \"perspective\"\n");
    CHECK_THAT(error_of([&] { read_scene_description(path); }),
               Catch::Contains("is not a scene file this renderer reads") && Catch::Contains(".json"));
    CHECK_THAT(error_of([&] { read_scene_description(folder.file("absent.json")); }), Catch::Contains("does not exist"));
}

TEST_CASE("a scene description that no file gave builds and renders, and the accelerator is built apart",
          "[unit][scene-input]") {
    // What a reader of another format would hand over: one emitting triangle facing the camera.
    SceneDescription description;
    description.file = "(made in a test)";
    description.camera.position = Vec3(0, 0, 3);
    description.camera.look_at = Vec3(0, 0, 0);
    description.camera.width = description.camera.height = 4;
    description.camera_block.path = "/camera";
    TriangleMesh mesh;
    mesh.name = "lamp";
    mesh.positions = {Vec3(-10, -10, 0), Vec3(10, -10, 0), Vec3(0, 10, 0)};
    mesh.triangles = {{0, 1, 2}};
    mesh.face_materials = {0};
    description.meshes.push_back(mesh);
    description.materials.push_back({"lamp", {{{"type", "diffuse"}, {"albedo", {0, 0, 0}}, {"emission", {2, 2, 2}}}, "(made)", "/lamp", true, {}}});

    SceneLoadOptions options;
    options.selections[CapabilityKind::Accelerator] = "bruteforce";
    Scene scene = build_scene(description, full_registry(), options);
    CHECK_FALSE(scene.accelerator_built);
    CHECK(scene.accelerator_name == "bruteforce");
    CHECK(scene.emissive_triangles.size() == 1);
    build_accelerator(scene);
    CHECK(scene.accelerator_built);
    CHECK(scene.accelerator_build_seconds >= 0.0);

    // Every pixel sees the emitter straight on: radiance 2 exactly.
    RenderSettings settings;
    settings.samples_per_pixel = 1;
    settings.threads = 1;
    const auto integrator = full_registry().integrators.make("pt-naive", "test", settings, Parameters::none());
    Progress quiet(true);
    const RenderResult result = integrator->render(scene, settings, quiet);
    for (std::size_t p = 0; p < result.image.pixel_count(); ++p) CHECK(result.image[p].r == 2.0f);
}
