// Grading tests of chapter 04's exercises. Each test case is named after its exercise, calls the
// exercise's own function first (so that in a student copy it fails through its own stub), and
// checks it against exact values. Deterministic: no statistical test in this file.
#include "freezeray/ch01/lambertian.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/ch04/bdpt_mis_weight.hpp"
#include "freezeray/ch04/light_tracer.hpp"

#include "full_paths.hpp"
#include "reference_blocks.hpp"
#include "statistics.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace freezeray;
using namespace freezeray::ch01;
using namespace freezeray::ch04;

namespace {

// The Cornell box with brute force, chapter 04's accelerator: the default KD-tree would run
// chapter 06's exercises, which a student of chapter 04 has not written yet.
Scene load_cornell_box() {
    SceneLoadOptions options;
    options.selections[CapabilityKind::Accelerator] = "bruteforce";
    return load_scene(testing::scene_path("cornell-box/scene.json"), testing::full_registry(), options);
}

}  // namespace

TEST_CASE("ch04/strategy-ratio", "[exercise]") {
    // Veach 1997, eq. 10.9: r_i = r_{i+1} p_rev / p_fwd, a zero density (a delta vertex) as 1.
    REQUIRE(next_strategy_ratio(2.0, 3.0f, 4.0f) == Approx(1.5));
    CHECK(next_strategy_ratio(1.0, 0.25f, 2.0f) == Approx(0.125));
    CHECK(next_strategy_ratio(2.0, 0.0f, 4.0f) == Approx(0.5));  // reverse density 0: taken as 1
    CHECK(next_strategy_ratio(2.0, 3.0f, 0.0f) == Approx(6.0));  // forward density 0: taken as 1
    CHECK(next_strategy_ratio(2.0, 0.0f, 0.0f) == Approx(2.0));
    // Densities far apart stay finite and exact in double (a tiny light, a huge one).
    CHECK(next_strategy_ratio(1.0, 1e30f, 1e-30f) == Approx(1e60).epsilon(1e-6));
    CHECK(next_strategy_ratio(1e-20, 1e-30f, 1e30f) == Approx(1e-80).epsilon(1e-6));

    // Used by bdpt's weights: on 50 complete paths of the Cornell box, the weights of every
    // strategy sum to one and equal the power heuristic written out with the full densities.
    const Scene scene = load_cornell_box();
    const ch03::FixedLightSampler lights(scene.lights, ch03::LightSelection::Power);
    const int checked = testing::for_paths_ending_on_emitters(scene, lights, 50, 41, [&](const testing::FullPath& path) {
        const int n = static_cast<int>(path.x.size());
        double sum = 0.0;
        for (int s = 0; s < n; ++s) {
            if (!testing::has_strategy(path, s)) continue;
            const float w = testing::weight_of(scene, lights, ch03::MisHeuristic::Power, path, s);
            INFO("path of " << n << " vertices, strategy s = " << s);
            CHECK(w == Approx(testing::direct_weight(path, s, ch03::MisHeuristic::Power)).epsilon(1e-3).margin(1e-6));
            sum += w;
        }
        CHECK(sum == Approx(1.0).epsilon(1e-4));
    });
    CHECK(checked == 50);
}

TEST_CASE("ch04/camera-connection", "[exercise]") {
    // A Lambertian point of the Cornell box seen off-centre: the value must be
    // beta (rho / pi) |cos theta_vertex| We / pdf, with We = 1 / (A cos^4 theta_camera) and
    // pdf = d^2 / cos theta_camera (the shading normal is the geometric one: no correction).
    const Scene scene = load_cornell_box();
    const auto& camera = dynamic_cast<const PinholeCamera&>(*scene.camera);  // the Cornell box's camera
    const Vec2 film(0.2f * static_cast<float>(camera.width()), 0.7f * static_cast<float>(camera.height()));
    const std::optional<Hit> hit = scene.intersect(camera.generate_ray(film));
    REQUIRE(hit.has_value());
    const Spectrum albedo(0.2f, 0.5f, 0.8f);
    const LambertianBSDF bsdf(albedo);
    const Vec3 wo_world = glm::normalize(hit->geometric_normal + Vec3(0.1f, 0.2f, 0.05f));  // towards the light
    const Frame frame = shading_frame(*hit, bsdf, wo_world);
    const Spectrum beta(2.0f, 3.0f, 4.0f);

    const std::optional<CameraConnection> connection = connect_to_camera(scene, *hit, bsdf, frame, wo_world, beta);
    REQUIRE(connection.has_value());
    const Vec3 to_camera = camera.position() - hit->position;
    const double d = glm::length(to_camera);
    const double cos_camera = glm::dot(glm::normalize(-to_camera), camera.forward());
    const double cos_vertex = std::abs(glm::dot(glm::normalize(to_camera), frame.n));
    const double importance = 1.0 / (camera.image_plane_area() * std::pow(cos_camera, 4.0));
    const double pdf = d * d / cos_camera;
    for (int c = 0; c < 3; ++c) {
        const double expected = beta[c] * (albedo[c] / 3.14159265358979323846) * cos_vertex * importance / pdf;
        INFO("channel " << c);
        CHECK(connection->value[c] == Approx(expected).epsilon(1e-4));
    }
    CHECK(connection->raster_position.x == Approx(film.x).margin(1e-2));
    CHECK(connection->raster_position.y == Approx(film.y).margin(1e-2));
}

TEST_CASE("ch04/bidirectional-path-tracer", "[exercise]") {
    // The assignment (tests/grading/assignments.json): this chapter's exercises together render the
    // Cornell box with bdpt as the solution does. 8 independent renders of 16 samples per pixel; each
    // block of pixels, and the whole image, against the solution's reference (make_references.py
    // --blocks, other seeds, 8 to 32 times the samples), false-failure rate exercise_test_alpha for
    // the whole comparison (reference_blocks.hpp).
    const testing::ReferenceComparison comparison =
        testing::compare_with_reference("ch04/bidirectional-path-tracer", 8, 16, 1, stats::exercise_test_alpha);
    INFO(comparison.message);
    INFO(comparison.evidence);
    CHECK(comparison.passed);
}
