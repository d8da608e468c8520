// Grading tests of chapter 03's exercises. Each test case is named after its exercise, calls the
// exercise's own function first (so that in a student copy it fails through its own stub), and
// checks it against exact values, and for the two densities a light's sampling against its pdf
// (chi-square, false-failure rate exercise_test_alpha each: 2 tests in this file).
#include "freezeray/ch03/area_light.hpp"
#include "freezeray/ch03/environment_light.hpp"
#include "freezeray/ch03/mis.hpp"

#include "bias_detectors.hpp"
#include "evidence.hpp"
#include "image_tests.hpp"
#include "light_chi_square.hpp"
#include "reference_blocks.hpp"
#include "statistics.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace freezeray;
using namespace freezeray::ch03;

namespace {

constexpr double pi = 3.14159265358979323846;

// A float result of a few operations: within 4 roundings.
constexpr double few_roundings = 4.0 * 0x1p-24;

// light.sample_li(reference, .) against light.pdf_li(reference, .) on the sphere
// (light_chi_square.hpp: samples that rounding put just across an edge are moved back, at most
// 1e-4 of them).
void check_light_sampling(const Light& light, const Vec3& reference, int resolution) {
    stats::ChiSquareOptions options;
    options.alpha = stats::exercise_test_alpha;
    options.resolution = resolution;
    const testing::LightChiSquare test = testing::light_chi_square_test(light, reference, options);
    INFO(test.result.message);
    const std::string evidence =
        test.result.passed
            ? ""
            : "evidence: " + stats::write_evidence(Catch::getResultCapture().getCurrentTestName(), test.result);
    INFO(evidence);
    CHECK(test.result.passed);
    CHECK(test.samples_moved_across_edges <= options.sample_count / 10000);
}

}  // namespace

TEST_CASE("ch03/power-heuristic", "[exercise]") {
    // Veach 1997, eq. 9.13 with beta = 2: w_f = (n_f p_f)^2 / ((n_f p_f)^2 + (n_g p_g)^2).
    // At p_f = 3 p_g the classic mistakes give values of their own (bias_detectors.hpp).
    const std::string hint = testing::likely_mistake(
        power_heuristic(1, 3.0f, 1, 1.0f),
        {{"the balance heuristic (beta = 1: n_f p_f / (n_f p_f + n_g p_g)), not the power heuristic", 0.75},
         {"the weight of the other strategy (n_g p_g)^2 / (...), not of f", 0.1},
         {"the ratio squared without 1 + (p_f^2 / p_g^2 instead of 1 / (1 + (p_g / p_f)^2))", 9.0}},
        1e-4);
    INFO(hint);
    REQUIRE(power_heuristic(1, 1.0f, 1, 1.0f) == Approx(0.5).epsilon(few_roundings));
    CHECK(power_heuristic(1, 3.0f, 1, 1.0f) == Approx(0.9).epsilon(few_roundings));   // 9 / 10, not 3 / 4
    CHECK(power_heuristic(1, 1.0f, 1, 2.0f) == Approx(0.2).epsilon(few_roundings));   // 1 / 5
    CHECK(power_heuristic(2, 1.0f, 1, 1.0f) == Approx(0.8).epsilon(few_roundings));   // the sample counts count
    CHECK(power_heuristic(1, 1.0f, 2, 1.5f) == Approx(0.1).epsilon(few_roundings));   // 1 / (1 + 9)
    CHECK(power_heuristic(1, 0.0f, 1, 5.0f) == 0.0f);  // f cannot produce the direction
    CHECK(power_heuristic(1, 5.0f, 1, 0.0f) == Approx(1.0).epsilon(few_roundings));
    // Densities whose squares overflow or underflow a float (a small light seen from far away):
    // still finite, and the two weights still sum to one (1e-6: the two weights' roundings).
    PCG32 random(4, 9);
    for (int i = 0; i < 1000; ++i) {
        const auto f = static_cast<float>(std::pow(10.0, 60.0 * random.next_float() - 30.0));
        const auto g = static_cast<float>(std::pow(10.0, 60.0 * random.next_float() - 30.0));
        const float w_f = power_heuristic(1, f, 1, g), w_g = power_heuristic(1, g, 1, f);
        INFO("p_f = " << f << ", p_g = " << g << ": weights " << w_f << " and " << w_g);
        REQUIRE(std::isfinite(w_f));
        REQUIRE(std::isfinite(w_g));
        REQUIRE(std::abs(double(w_f) + double(w_g) - 1.0) <= 1e-6);
        // Against the formula in double where it does not overflow.
        const double ratio = double(g) / double(f);
        REQUIRE(w_f == Approx(1.0 / (1.0 + ratio * ratio)).epsilon(few_roundings).margin(1e-7));
    }
    CHECK(power_heuristic(1, 1e30f, 1, 1e30f) == Approx(0.5).epsilon(few_roundings));
    CHECK(power_heuristic(1, 1e-30f, 1, 1e-30f) == Approx(0.5).epsilon(few_roundings));
}

TEST_CASE("ch03/environment-pdf", "[exercise]") {
    // d omega = sin theta d theta d phi = 2 pi^2 sin theta du dv (pbrt-v3, eq. 14.8), so
    // p(omega) = p(u, v) / (2 pi^2 sin theta).
    REQUIRE(equirectangular_to_solid_angle_pdf(1.0f, 1.0f) == Approx(1.0 / (2.0 * pi * pi)).epsilon(few_roundings));
    CHECK(equirectangular_to_solid_angle_pdf(3.0f, 0.5f) == Approx(3.0 / (pi * pi)).epsilon(few_roundings));
    CHECK(equirectangular_to_solid_angle_pdf(0.25f, 0.01f) == Approx(12.5 / (pi * pi)).epsilon(few_roundings));
    CHECK(equirectangular_to_solid_angle_pdf(0.0f, 0.7f) == 0.0f);
    // A uniform image: its pixel weights are sin theta at the rows' centres, so at a row's centre
    // pdf_uv = sin theta / mean(sin theta_y) and pdf_li = 1 / (2 pi^2 mean(sin theta_y)), within
    // 1e-4 of the uniform 1 / (4 pi) for 64 rows (the midpoint rule's error for the integral of
    // sin theta); exact here, in double, up to float rounding in the weights and the sines.
    const int rows = 64;
    double mean_sin = 0.0;
    for (int y = 0; y < rows; ++y) mean_sin += std::sin(pi * (y + 0.5) / rows) / rows;
    const EnvironmentMapLight uniform(Image(2 * rows, rows, Spectrum(1.0f)), Spectrum(1.0f), Mat3(1.0f));
    for (const int y : {3, 20, 32, 50, 63}) {
        const Vec3 d = equirectangular_to_direction(Vec2(0.37f, static_cast<float>((y + 0.5) / rows)));
        INFO("row " << y);
        CHECK(uniform.pdf_li(Vec3(0.0f), d) == Approx(1.0 / (2.0 * pi * pi * mean_sin)).epsilon(1e-5));
    }
    // A peaked map (one pixel 1e4 times the rest, black poles), rotated: its directions against
    // pdf_li, which also integrates to one over the sphere.
    Image peaked(16, 8, Spectrum(1.0f));
    for (int x = 0; x < 16; ++x) peaked.at(x, 0) = peaked.at(x, 7) = Spectrum(0.0f);
    peaked.at(5, 2) = Spectrum(1e4f);
    const Mat3 rotation(glm::rotate(Mat4(1.0f), glm::radians(30.0f), glm::normalize(Vec3(1.0f, 0.0f, 1.0f))));
    const EnvironmentMapLight light(peaked, Spectrum(1.0f), rotation);
    check_light_sampling(light, Vec3(0.0f), 20);
}

TEST_CASE("ch03/area-to-solid-angle", "[exercise]") {
    // dA = r^2 / |cos theta_light| d omega (Veach 1997, eq. 8.10): p_omega = p_A r^2 / cos.
    // With p_A = 2, r^2 = 9 and cos = 0.5 (right: 36) the classic mistakes give values of their own.
    const std::string hint = testing::likely_mistake(
        area_to_solid_angle_pdf(2.0f, 9.0f, 0.5f),
        {{"the area density returned unconverted (a density per area, not per solid angle)", 2.0},
         {"the cosine at the light is missing (p_A r^2)", 18.0},
         {"multiplied by the cosine instead of divided (p_A r^2 cos)", 9.0},
         {"the distance not squared (p_A r / cos)", 12.0},
         {"the conversion inverted (p_A cos / r^2, solid angle to area)", 2.0 * 0.5 / 9.0}},
        1e-4);
    INFO(hint);
    REQUIRE(area_to_solid_angle_pdf(0.5f, 4.0f, 0.25f) == Approx(8.0).epsilon(few_roundings));
    CHECK(area_to_solid_angle_pdf(1.0f, 1.0f, 1.0f) == Approx(1.0).epsilon(few_roundings));
    CHECK(area_to_solid_angle_pdf(2.0f, 9.0f, 0.5f) == Approx(36.0).epsilon(few_roundings));
    CHECK(area_to_solid_angle_pdf(0.1f, 100.0f, 1.0f) == Approx(10.0).epsilon(few_roundings));
    // A triangle light's density towards its directions: sample_li against pdf_li from a point
    // in front of it, 1.5 above (the triangle covers about a steradian); the pdf integrates to 1.
    TriangleMesh mesh;
    mesh.positions = {Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};
    mesh.triangles = {{0u, 1u, 2u}};
    const TriangleLight light(mesh, 0, Spectrum(1.0f));
    const Vec3 reference(0.3f, -0.2f, 1.5f);
    const auto s = light.sample_li(reference, Vec2(0.3f, 0.4f));
    REQUIRE(s);
    // Uniform by area (1 / A = 1 / 2), then converted: r^2 / (A cos).
    const Vec3 to_light = s->position - reference;
    const double cos_light = -to_light.z / glm::length(to_light);  // at the light, whose normal is +z
    CHECK(s->pdf == Approx(glm::dot(to_light, to_light) / (2.0 * cos_light)).epsilon(1e-5));
    check_light_sampling(light, reference, 10);
}

TEST_CASE("ch03/emission-weight", "[exercise]") {
    // Emission must be counted once in all. The furnace (Le = 0.5, albedo 0.5 everywhere) with
    // paths of two segments gives exactly Le (1 + rho) = 0.75 with pt-nee and with pt-mis: Le seen
    // by the camera, and rho Le found once at the first bounce, by the light sample, the BSDF
    // sample, or both weighted by MIS. Each mistake has its own answer (bias_detectors.hpp): the
    // second part counted twice 1.0, the camera's Le dropped 0.25. Then the white mirror and the
    // white diffuse sphere under a constant sky of radiance 1 are 1 everywhere with pt-nee: the
    // sky seen through a delta bounce is found only by the BSDF sample, and counts in full. Each
    // mean against its exact value by a t-test at false-failure rate exercise_test_alpha (4 tests).
    testing::TestRender request;
    request.scene = testing::scene_path("furnace/scene.json");
    request.samples_per_pixel = 16;
    request.width = 16;
    request.height = 16;
    request.seed = 9;
    request.max_depth = 2;
    request.accelerator = "bruteforce";
    for (const char* integrator : {"pt-nee", "pt-mis"}) {
        request.integrator = integrator;
        const RenderResult result = testing::render(request);
        const std::vector<double> values = stats::channel_values(result.image, 1);
        const stats::TestResult test = stats::one_sample_t_test(values, 0.75, stats::exercise_test_alpha);
        const double mean = stats::estimate_mean(values).mean;
        const std::string hint =
            test.passed ? ""
                        : testing::likely_mistake(
                              mean,
                              {{"emission counted twice: found by the BSDF sample in full and by the light sample too "
                                "(its weight must be 0 for next-event estimation, the MIS weight for MIS)", 1.0},
                               {"the emission the camera sees directly is dropped (the camera ray is not a light sample: "
                                "weight 1)", 0.25}},
                              0.03);
        INFO(integrator << ": " << test.message);
        INFO(hint);
        CHECK(test.passed);
    }
    request.integrator = "pt-nee";
    request.max_depth = 0;
    for (const char* scene : {"hard/environment-furnace/mirror.json", "furnace/scene-environment.json"}) {
        request.scene = testing::scene_path(scene);
        const std::vector<double> values = stats::channel_values(testing::render(request).image, 1);
        const stats::TestResult test = stats::one_sample_t_test(values, 1.0, stats::exercise_test_alpha);
        const double mean = stats::estimate_mean(values).mean;
        INFO(scene << ": " << test.message);
        INFO((test.passed || mean > 1.0 ? ""
                                        : "likely mistake: emission found through a delta bounce (a mirror) weighted "
                                          "0: light sampling cannot find it, so it must count in full"));
        CHECK(test.passed);
    }
}

TEST_CASE("ch03/multiple-importance-sampling", "[exercise]") {
    // The assignment (tests/grading/assignments.json): this chapter's exercises together render the
    // material spheres with pt-mis, lit by their area light and by an environment map as the solution
    // does. 8 independent renders of 32 samples per pixel; each block of pixels, and the whole image,
    // against the solution's reference (make_references.py --blocks, other seeds, 8 to 32 times the
    // samples), false-failure rate exercise_test_alpha for the whole comparison
    // (reference_blocks.hpp).
    const testing::ReferenceComparison comparison =
        testing::compare_with_reference("ch03/multiple-importance-sampling", 8, 32, 1, stats::exercise_test_alpha);
    INFO(comparison.message);
    INFO(comparison.evidence);
    CHECK(comparison.passed);
}
