// Chapter 03's lights: every light's sample_li against its own pdf_li, as seen from reference
// points in front of, grazing, close to and far from an area light, and for environments (a
// constant one, and equirectangular maps from varied to strongly peaked, also rotated); and the
// piecewise-constant distributions under them. Each asserted chi-square test is one test at
// chi_square_test_alpha (tests/STATISTICS.md): 11 in this file.
//
// A sampler that sometimes returns nothing has a pdf integrating to its success probability
// (STATISTICS.md); from in front of a one-sided emitter sample_li always succeeds, so its pdf
// integrates to 1. From behind it never succeeds: that case is checked exactly (there is no
// histogram to compare). Delta lights have no density: tests/unit/test_ch03_lights.cpp checks
// them exactly.
#include "freezeray/ch03/area_light.hpp"
#include "freezeray/ch03/environment_light.hpp"
#include "freezeray/ch03/piecewise_constant.hpp"

#include "evidence.hpp"
#include "light_chi_square.hpp"

#include "environment_images.hpp"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <sstream>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch03;

namespace {

void require_passes(const stats::ChiSquareResult& result, const std::string& name) {
    if (!result.passed) {
        const std::string folder = stats::write_evidence(name, result);
        FAIL(name << "\n" << result.message << "\nevidence: " << folder);
    }
    SUCCEED(name << ": " << result.message);
}

struct Chi2Request {
    std::uint64_t sample_count = 1'000'000;
    int resolution = 10;
    std::optional<double> expected_pdf_integral = 1.0;
    // Directions are binned turned by this rotation (and turned back for the pdf): the harness's
    // cells are slivers near its poles (+-z), where a small light's outline can cut cells into
    // pieces its quadrature misses; turned to the equator, the cells are nearly square.
    Mat3 view = Mat3(1.0f);
};

// The chi-square test of a light's sampling (light_chi_square.hpp), failing the test case with
// its message and evidence; and at most 1e-4 of the samples moved across an edge (rounding errors
// a few times 1e-7 make a band of about 1e-6 of a pixel or of the triangle around the edges).
void check_light(const Light& light, const Vec3& reference, const std::string& name, const Chi2Request& request = {}) {
    stats::ChiSquareOptions options;
    options.sample_count = request.sample_count;
    options.resolution = request.resolution;
    options.expected_pdf_integral = request.expected_pdf_integral;
    const testing::LightChiSquare test = testing::light_chi_square_test(light, reference, options, request.view);
    std::ostringstream what;
    what << name << " from (" << reference.x << ", " << reference.y << ", " << reference.z << "), "
         << test.samples_moved_across_edges << " samples moved across an edge";
    require_passes(test.result, what.str());
    CHECK(test.samples_moved_across_edges <= request.sample_count / 10000);
}

// One triangle in the plane z = 0, emitting towards +z (its winding's normal).
TriangleMesh emitter_mesh() {
    TriangleMesh mesh;
    mesh.name = "emitter";
    mesh.positions = {Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};
    mesh.triangles = {{0u, 1u, 2u}};
    mesh.face_materials = {0u};
    return mesh;
}

// A 16 x 8 map, rows 0 and 7 (the poles) black, the rest 1, and one pixel 1e5 times brighter at
// (10, 1), beside the black top row: nearly every sample lands in it.
Image peaked_image() {
    Image image(16, 8, Spectrum(1.0f));
    for (int x = 0; x < 16; ++x) image.at(x, 0) = image.at(x, 7) = Spectrum(0.0f);
    image.at(10, 1) = Spectrum(1e5f, 0.8e5f, 1.2e5f);
    return image;
}

}  // namespace

TEST_CASE("a triangle light's sample_li matches its pdf_li in front, grazing, close and far", "[chi2][lights][ch03]") {
    const TriangleMesh mesh = emitter_mesh();
    const TriangleLight light(mesh, 0, Spectrum(2.0f));
    // In front, over the middle: the triangle covers about a steradian.
    check_light(light, Vec3(0.2f, 0.1f, 1.5f), "triangle-front");
    // Close: 0.01 above the surface, the triangle covers nearly the whole lower hemisphere and
    // the density d^2 / (A cos) varies by orders of magnitude towards its edges.
    Chi2Request close;
    close.resolution = 20;
    check_light(light, Vec3(0.1f, -0.2f, 0.01f), "triangle-close", close);
    // Grazing: 0.25 above the plane, 1 to 3 away; cos at the light from 0.08 to 0.25, the
    // triangle a band below the horizon 0.16 high in cos(theta), which finer cells resolve.
    Chi2Request grazing;
    grazing.resolution = 40;
    check_light(light, Vec3(0.3f, -2.0f, 0.25f), "triangle-grazing", grazing);
    // Far: 6 away, about 0.05 sr, seen from above: turned to the harness's equator (-z to -x),
    // a dozen cells of the finer grid.
    Chi2Request far;
    far.resolution = 40;
    far.view = testing::rotation(90.0f, Vec3(0.0f, 1.0f, 0.0f));
    check_light(light, Vec3(2.0f, 1.0f, 5.5f), "triangle-far", far);
}

TEST_CASE("a triangle light sends nothing behind itself nor along its plane", "[chi2][lights][ch03]") {
    // The emitter is one-sided: from behind, sample_li never succeeds and pdf_li is zero
    // everywhere, so the success probability (0) is the pdf's integral. Exact, not statistical.
    const TriangleMesh mesh = emitter_mesh();
    const TriangleLight light(mesh, 0, Spectrum(2.0f));
    PCG32 random(5, 3);
    for (const Vec3 reference : {Vec3(0.1f, 0.2f, -1.0f), Vec3(0.0f, 0.0f, -1e-3f), Vec3(3.0f, 0.5f, 0.0f)}) {
        INFO("reference (" << reference.x << ", " << reference.y << ", " << reference.z << ")");
        for (int i = 0; i < 10000; ++i) CHECK_FALSE(light.sample_li(reference, Vec2(random.next_float(), random.next_float())));
        // Directions straight at the triangle's points, which do meet it from behind.
        for (const Vec3 target : {Vec3(0.0f, -0.3f, 0.0f), Vec3(0.5f, -0.9f, 0.0f), Vec3(0.0f, 0.9f, 0.0f)})
            CHECK(light.pdf_li(reference, glm::normalize(target - reference)) == 0.0f);
        CHECK(stats::integrate_over_domain(stats::Domain::sphere(), [&](const Vec3& wi) {
                  return static_cast<double>(light.pdf_li(reference, wi));
              }) == 0.0);
    }
}

TEST_CASE("the constant environment's sample_li matches its pdf_li", "[chi2][lights][ch03]") {
    const ConstantEnvironmentLight light(Spectrum(0.5f, 1.0f, 2.0f));
    check_light(light, Vec3(1.0f, -2.0f, 3.0f), "constant-environment");
}

TEST_CASE("an environment map's sample_li matches its pdf_li: varied, peaked, rotated", "[chi2][lights][ch03]") {
    // The varied map's bottom row is bright: pdf_li grows like 1 / sin theta towards that pole
    // (a row of pixels is squeezed into a cap), integrable but not on the harness's grid points:
    // the pole of the map (its -y) is turned away from them, 17 degrees.
    const EnvironmentMapLight varied(testing::varied_environment_image(), Spectrum(1.0f), testing::rotation(17.0f, Vec3(1.0f, 0.3f, 0.2f)));
    check_light(varied, Vec3(0.0f), "environment-varied", {1'000'000, 20, 1.0});
    // The peak covers 22.5 x 22.5 degrees: cells of 4.5 degrees x 0.05 in cos(theta) see its shape.
    const EnvironmentMapLight peaked(peaked_image(), Spectrum(1.0f), Mat3(1.0f));
    check_light(peaked, Vec3(4.0f, 5.0f, -6.0f), "environment-peaked", {1'000'000, 40, 1.0});
    const EnvironmentMapLight rotated(peaked_image(), Spectrum(2.0f), testing::rotation(50.0f, Vec3(1.0f, 2.0f, 0.5f)));
    check_light(rotated, Vec3(0.0f), "environment-peaked-rotated", {1'000'000, 40, 1.0});
}

TEST_CASE("PiecewiseConstant1D's continuous samples match its pdf", "[chi2][lights][ch03]") {
    // Ten steps (not a power of two, so (i + within) / n rounds), five of them zero; and seven
    // steps all zero. Cells of 1/70, seven per step of ten, ten per step of seven: no cell
    // straddles a step's edge.
    const std::vector<float> values{0.0f, 3.0f, 0.0f, 0.0f, 1.0f, 7.0f, 0.5f, 0.0f, 2.0f, 0.0f};
    // All zero: the uniform density.
    const std::vector<float> zeros(7, 0.0f);
    for (const auto& table : {values, zeros}) {
        const PiecewiseConstant1D distribution(table);
        stats::ChiSquareOptions options;
        options.resolution = 70;
        const auto result = stats::chi_square_test(
            stats::Domain::interval(0.0, 1.0),
            [&](PCG32& r) -> std::optional<Vec3> {
                const PiecewiseConstant1D::Continuous s = distribution.sample_continuous(r.next_float());
                // The density it reports is the pdf at the point (checked here, exactly).
                if (s.pdf != distribution.pdf(s.x)) return Vec3(-1.0f);  // counted as outside the domain
                return Vec3(s.x, 0.0f, 0.0f);
            },
            [&](const Vec3& p) { return static_cast<double>(distribution.pdf(p.x)); }, options);
        require_passes(result, table.size() == values.size() ? "piecewise-1d" : "piecewise-1d-all-zero");
    }
}

TEST_CASE("PiecewiseConstant2D's samples match its pdf", "[chi2][lights][ch03]") {
    // 5 x 3 values with zeros, a zero column entry per row and values over four orders of
    // magnitude; cells of 1/30 align with the steps (1/5 and 1/3).
    const std::vector<float> values{1.0f, 0.0f, 4.0f, 0.01f, 2.0f,   //
                                    0.0f, 0.0f, 0.0f, 0.0f, 0.0f,    // a zero row
                                    5.0f, 100.0f, 0.0f, 3.0f, 0.5f};
    const PiecewiseConstant2D distribution(values, 5, 3);
    stats::ChiSquareOptions options;
    options.resolution = 30;
    const auto result = stats::chi_square_test(
        stats::Domain::unit_square(),
        [&](PCG32& r) -> std::optional<Vec3> {
            const PiecewiseConstant2D::Sample s = distribution.sample(r.next_float(), r.next_float());
            if (s.pdf != distribution.pdf(s.u, s.v)) return Vec3(-1.0f);  // counted as outside the domain
            return Vec3(s.u, s.v, 0.0f);
        },
        [&](const Vec3& p) { return static_cast<double>(distribution.pdf(p.x, p.y)); }, options);
    require_passes(result, "piecewise-2d");
}
