// Chapter 03's lights, checked exactly: the delta lights' sample_li (which no chi-square test can
// see), the equirectangular map and its density, piecewise-constant distributions, and every
// light's power against its closed form. Deterministic: no statistical test in this file.
// Sampling against densities is in tests/chi2/test_ch03_lights.cpp; light selection and MIS
// weights in test_ch03_mis.cpp.
#include "freezeray/ch03/area_light.hpp"
#include "freezeray/ch03/directional_light.hpp"
#include "freezeray/ch03/environment_light.hpp"
#include "freezeray/ch03/piecewise_constant.hpp"
#include "freezeray/ch03/point_light.hpp"
#include "freezeray/ch03/spot_light.hpp"

#include "chi_square.hpp"

#include "environment_images.hpp"

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch03;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double float_epsilon = 0x1p-24;  // a float rounding's relative error

// The relative error bound of pdf_li at a direction of polar angle theta (in the light's frame),
// from float arithmetic: a dozen roundings of 2^-24 in the density, plus sin theta taken as
// sqrt(x^2 + z^2) from components each off by a few roundings in absolute terms (the rotation,
// or sin(pi v) for the direction), a relative error of a few 2^-24 / sin theta.
double pdf_li_relative_error(double sin_theta) {
    return 16.0 * float_epsilon + 8.0 * float_epsilon / sin_theta;
}

}  // namespace

TEST_CASE("a point light sends I / r^2 along the only direction towards it", "[unit][lights][ch03]") {
    const PointLight light(Vec3(1.0f, 2.0f, 3.0f), Spectrum(4.0f, 8.0f, 12.0f));
    CHECK(light.type() == LightType::DeltaPosition);
    CHECK(is_delta_light(light.type()));
    const auto s = light.sample_li(Vec3(1.0f, 2.0f, 1.0f), Vec2(0.3f, 0.7f));  // 2 below it
    REQUIRE(s);
    CHECK(s->wi == Vec3(0.0f, 0.0f, 1.0f));
    CHECK(s->radiance == Spectrum(1.0f, 2.0f, 3.0f));  // I / 4, exact in float
    CHECK(s->pdf == 1.0f);
    CHECK(s->position == Vec3(1.0f, 2.0f, 3.0f));
    CHECK_FALSE(s->infinite);
    // Oblique, at distance 5 (a 3-4-5 triangle): I / 25.
    const auto oblique = light.sample_li(Vec3(4.0f, 6.0f, 3.0f), Vec2(0.0f));
    REQUIRE(oblique);
    CHECK(oblique->wi.x == Approx(-0.6f).epsilon(1e-6));
    CHECK(oblique->wi.y == Approx(-0.8f).epsilon(1e-6));
    CHECK(oblique->radiance.b == Approx(12.0f / 25.0f).epsilon(1e-6));
    // At the light itself no direction exists; no direction has a density.
    CHECK_FALSE(light.sample_li(Vec3(1.0f, 2.0f, 3.0f), Vec2(0.5f)));
    CHECK(light.pdf_li(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f)) == 0.0f);
}

TEST_CASE("a spot light: full inside, smoothstep in the falloff band, nothing outside", "[unit][lights][ch03]") {
    // Pointing down (-z) from the origin; cone 30 degrees, falloff from 20.
    const double cos_cone = std::cos(30.0 * pi / 180.0), cos_start = std::cos(20.0 * pi / 180.0);
    const SpotLight light(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), Spectrum(10.0f, 20.0f, 40.0f), static_cast<float>(cos_cone),
                          static_cast<float>(cos_start));
    // A reference point 2 away at `degrees` from the axis.
    const auto at = [](double degrees) {
        const double a = degrees * pi / 180.0;
        return Vec3(static_cast<float>(2.0 * std::sin(a)), 0.0f, static_cast<float>(-2.0 * std::cos(a)));
    };
    for (double degrees : {0.0, 10.0, 19.0}) {
        const auto s = light.sample_li(at(degrees), Vec2(0.5f));
        REQUIRE(s);
        CHECK(s->radiance.g == Approx(20.0f / 4.0f).epsilon(1e-6));
        CHECK(glm::length(s->wi + glm::normalize(at(degrees))) == Approx(0.0f).margin(1e-6));
        CHECK(s->pdf == 1.0f);
    }
    for (double degrees : {21.0, 25.0, 29.0}) {
        // pbrt-v4's falloff: smoothstep of t = (cos - cos_cone) / (cos_start - cos_cone).
        const double t = (std::cos(degrees * pi / 180.0) - cos_cone) / (cos_start - cos_cone);
        const double expected = 20.0 / 4.0 * t * t * (3.0 - 2.0 * t);
        const auto s = light.sample_li(at(degrees), Vec2(0.5f));
        REQUIRE(s);
        INFO(degrees << " degrees from the axis");
        // float cosines near 1 lose about 2^-24 / (cos_start - cos_cone) of t: 2e-6 relative.
        CHECK(s->radiance.g == Approx(expected).epsilon(1e-5));
    }
    CHECK(light.falloff(static_cast<float>(cos_start)) == 1.0f);
    CHECK(light.falloff(static_cast<float>(cos_cone)) == 0.0f);
    for (double degrees : {31.0, 60.0, 90.0, 180.0}) CHECK_FALSE(light.sample_li(at(degrees), Vec2(0.5f)));
    CHECK(light.pdf_li(at(0.0), Vec3(0.0f, 0.0f, 1.0f)) == 0.0f);
}

TEST_CASE("a directional light arrives from one direction at infinity", "[unit][lights][ch03]") {
    DirectionalLight light(Vec3(1.0f, -2.0f, 0.5f), Spectrum(3.0f));
    CHECK(light.type() == LightType::DeltaDirection);
    for (const Vec3 reference : {Vec3(0.0f), Vec3(100.0f, -3.0f, 7.0f)}) {
        const auto s = light.sample_li(reference, Vec2(0.1f, 0.9f));
        REQUIRE(s);
        CHECK(glm::length(s->wi + glm::normalize(Vec3(1.0f, -2.0f, 0.5f))) == Approx(0.0f).margin(1e-6));
        CHECK(s->radiance == Spectrum(3.0f));  // the irradiance: a delta in direction
        CHECK(s->pdf == 1.0f);
        CHECK(s->infinite);
        CHECK(light.pdf_li(reference, s->wi) == 0.0f);
    }
}

TEST_CASE("equirectangular coordinates: documented anchors and round trips", "[unit][lights][ch03]") {
    // The convention of environment_light.hpp and scenes/README.md.
    const auto uv = [](float x, float y, float z) { return direction_to_equirectangular(Vec3(x, y, z)); };
    CHECK(uv(0, 0, -1).x == 0.0f);
    CHECK(uv(1, 0, 0).x == Approx(0.25f).epsilon(1e-6));
    CHECK(uv(0, 0, 1).x == Approx(0.5f).epsilon(1e-6));
    CHECK(uv(-1, 0, 0).x == Approx(0.75f).epsilon(1e-6));
    CHECK(uv(1, 0, 0).y == Approx(0.5f).epsilon(1e-6));
    CHECK(uv(0, 1, 0).y == 0.0f);            // top row: straight up
    CHECK(uv(0, -1, 0).y == OneMinusEpsilon);  // bottom row, kept inside [0, 1)
    // Direction -> (u, v) -> direction, uniform over the sphere. The angles come back through
    // acos and atan2 of components each off by a few roundings, which near the poles turns an
    // error dy into d theta = dy / sin theta: allowed 1e-6 / sin theta (about 16 roundings).
    PCG32 random(3, 11);
    for (int i = 0; i < 100000; ++i) {
        const float z = 1.0f - 2.0f * random.next_float(), phi = 2.0f * Pi * random.next_float();
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const Vec3 d = glm::normalize(Vec3(r * std::cos(phi), z, r * std::sin(phi)));
        const Vec2 p = direction_to_equirectangular(d);
        REQUIRE((p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f));
        const Vec3 back = equirectangular_to_direction(p);
        const double sin_theta = std::sqrt(std::max(1e-12, 1.0 - double(d.y) * d.y));
        INFO("direction (" << d.x << ", " << d.y << ", " << d.z << ")");
        REQUIRE(glm::length(back - d) <= 1e-6 / sin_theta);
    }
}

TEST_CASE("an environment map's pdf_li integrates to one over the sphere", "[unit][lights][ch03]") {
    // With theta = pi v and phi = 2 pi u, d omega = 2 pi^2 sin theta du dv, and pdf_li sin theta
    // 2 pi^2 is the image-space density, constant on each pixel. The midpoint rule on a grid of
    // 4 x 4 points per pixel is therefore exact; what is left is float rounding, bounded term by
    // term with pdf_li_relative_error (largest near the poles, where sin theta is small).
    const Image image = testing::varied_environment_image();
    for (const Mat3& light_to_world : {Mat3(1.0f), testing::rotation(70.0f, Vec3(0.3f, -1.0f, 2.0f))}) {
        const EnvironmentMapLight light(image, Spectrum(1.0f), light_to_world);
        const int nu = image.width() * 4, nv = image.height() * 4;
        double integral = 0.0, error_bound = 0.0;
        for (int j = 0; j < nv; ++j) {
            const double v = (j + 0.5) / nv, sin_theta = std::sin(pi * v);
            for (int i = 0; i < nu; ++i) {
                const double u = (i + 0.5) / nu;
                const Vec3 d = light_to_world * equirectangular_to_direction(Vec2(static_cast<float>(u), static_cast<float>(v)));
                const double term = light.pdf_li(Vec3(0.0f), d) * sin_theta * 2.0 * pi * pi / (double(nu) * nv);
                integral += term;
                error_bound += term * pdf_li_relative_error(sin_theta);
            }
        }
        INFO("integral " << integral << ", float rounding bound " << error_bound);
        CHECK(std::abs(integral - 1.0) <= error_bound);
    }
}

TEST_CASE("an environment map's pdf_li is the density its sample_li reports", "[unit][lights][ch03]") {
    // The same pixel gives the same density, up to rounding (pdf_li_relative_error). A direction
    // within rounding of a pixel's edge can come back in the neighbouring pixel (about one
    // sample in a million): such a mismatch is accepted only that close to an edge. The map's
    // bottom rows are bright: 1e6 samples put about 12 within 3.5e-4 radians of its pole, where
    // y rounds to -1 (pdf_li once took sin theta from y there, and returned 0).
    const Mat3 light_to_world = testing::rotation(-35.0f, Vec3(1.0f, 1.0f, 0.0f));
    const Image image = testing::varied_environment_image();
    const EnvironmentMapLight light(image, Spectrum(1.0f), light_to_world);
    PCG32 random(8, 2);
    int at_edges = 0;
    for (int i = 0; i < 1000000; ++i) {
        const auto s = light.sample_li(Vec3(1.0f, 2.0f, 3.0f), Vec2(random.next_float(), random.next_float()));
        REQUIRE(s);
        REQUIRE(s->infinite);
        REQUIRE(glm::length(s->wi) == Approx(1.0f).epsilon(1e-6));
        const Vec3 local = glm::transpose(light_to_world) * s->wi;
        const double sin_theta = std::sqrt(std::max(0.0, 1.0 - double(local.y) * local.y));
        const double pdf = light.pdf_li(Vec3(-5.0f), s->wi);  // the reference does not matter
        if (std::abs(pdf - s->pdf) <= pdf_li_relative_error(sin_theta) * s->pdf) continue;
        const Vec2 p = direction_to_equirectangular(local);
        const double px = p.x * image.width(), py = p.y * image.height();
        // Edges between two pixels: every column edge (u wraps around), the row edges but the
        // top and bottom of the image (the poles, where no neighbour is).
        const double row_edge = std::clamp(std::round(py), 1.0, image.height() - 1.0);
        const double to_edge = std::min(std::abs(px - std::round(px)), std::abs(py - row_edge));
        INFO("sample " << i << ": pdf " << s->pdf << ", pdf_li " << pdf << ", " << to_edge << " pixel from an edge");
        REQUIRE(to_edge < 1e-4);
        ++at_edges;
    }
    CHECK(at_edges <= 20);  // 2e-5 of the samples: the band of rounding is about 1e-6 of a pixel
}

TEST_CASE("PiecewiseConstant1D: discrete probabilities, the all-zero case, zero steps never chosen", "[unit][lights][ch03]") {
    const std::vector<float> values{0.0f, 3.0f, 0.0f, 0.0f, 1.0f, 7.0f, 0.5f, 0.0f, 2.0f, 0.0f};
    const PiecewiseConstant1D distribution(values);
    const double sum = 13.5;
    CHECK(distribution.integral() == Approx(sum / 10.0).epsilon(1e-12));
    double total = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        // Each probability is a difference of double cdf values rounded once to float.
        CHECK(distribution.discrete_probability(i) == Approx(values[i] / sum).epsilon(2.0 * float_epsilon).margin(1e-12));
        total += distribution.discrete_probability(i);
    }
    CHECK(std::abs(total - 1.0) <= 10.0 * float_epsilon);  // ten roundings at most
    // Every u of a fine grid, then the floats next to each step's edges and the extremes.
    const int grid = 100000;
    std::vector<float> us;
    for (int k = 0; k < grid; ++k) us.push_back(static_cast<float>(k) / grid);
    us.push_back(OneMinusEpsilon);
    double edge = 0.0;
    for (float v : values) {
        edge += v / sum;
        const auto e = static_cast<float>(edge);
        for (float u : {std::nextafter(e, 0.0f), e, std::nextafter(e, 1.0f)})
            if (u < 1.0f) us.push_back(u);
    }
    std::vector<std::size_t> chosen(values.size(), 0);
    for (std::size_t k = 0; k < us.size(); ++k) {
        const float u = us[k];
        const std::size_t i = distribution.sample_discrete(u);
        REQUIRE(i < values.size());
        INFO("u = " << u);
        REQUIRE(values[i] > 0.0f);
        if (k < static_cast<std::size_t>(grid)) ++chosen[i];
        const PiecewiseConstant1D::Continuous c = distribution.sample_continuous(u);
        REQUIRE(values[c.offset] > 0.0f);
        REQUIRE((c.x >= 0.0f && c.x < 1.0f));
        REQUIRE(distribution.pdf(c.x) > 0.0f);  // the point lies in its own (positive) step
        REQUIRE(c.pdf == distribution.pdf(c.x));
    }
    // On the uniform grid each step is chosen for a share of its points within one grid step
    // (1e-5) of its probability; 2e-5 with the float rounding of k / grid.
    for (std::size_t i = 0; i < values.size(); ++i)
        CHECK(static_cast<double>(chosen[i]) / grid == Approx(values[i] / sum).margin(2e-5));

    // All zero: nothing to follow, so uniform.
    const PiecewiseConstant1D zeros(std::vector<float>(4, 0.0f));
    CHECK(zeros.integral() == 0.0);
    for (std::size_t i = 0; i < 4; ++i) CHECK(zeros.discrete_probability(i) == 0.25f);
    CHECK(zeros.sample_discrete(0.6f) == 2u);
    CHECK(zeros.pdf(0.3f) == 1.0f);
    CHECK(zeros.sample_continuous(0.6f).x == Approx(0.6f).epsilon(1e-6));
    CHECK(zeros.sample_continuous(0.6f).pdf == 1.0f);
}

TEST_CASE("every light's power matches its closed form", "[unit][lights][ch03]") {
    SECTION("point: 4 pi I") {
        const PointLight light(Vec3(1.0f), Spectrum(1.0f, 2.0f, 3.0f));
        for (int c = 0; c < 3; ++c) CHECK(light.power()[c] == Approx(4.0 * pi * (c + 1)).epsilon(1e-6));
    }
    SECTION("spot: 2 pi I ((1 - cos_start) + (cos_start - cos_cone) / 2), the integral of its falloff") {
        const double cos_cone = std::cos(40.0 * pi / 180.0), cos_start = std::cos(15.0 * pi / 180.0);
        const SpotLight light(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), Spectrum(2.0f), static_cast<float>(cos_cone),
                              static_cast<float>(cos_start));
        const double closed = 2.0 * pi * 2.0 * ((1.0 - cos_start) + (cos_start - cos_cone) / 2.0);
        CHECK(light.power().r == Approx(closed).epsilon(1e-5));
        // The same by quadrature of what sample_li sends (I falloff over the sphere; adaptive
        // Simpson to 1e-6 per cell, on float cosines: 1e-5).
        const double integral = stats::integrate_over_domain(
            stats::Domain::sphere(), [&](const Vec3& w) { return 2.0 * light.falloff(w.z); }, 20);
        CHECK(integral == Approx(closed).epsilon(1e-5));
    }
    SECTION("triangle: pi A Le, one-sided") {
        TriangleMesh mesh;
        mesh.positions = {Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};  // A = 2
        mesh.triangles = {{0u, 1u, 2u}};
        const TriangleLight light(mesh, 0, Spectrum(0.5f, 1.0f, 3.0f));
        CHECK(light.area() == Approx(2.0f).epsilon(1e-6));
        CHECK(light.power().r == Approx(pi * 2.0 * 0.5).epsilon(1e-6));
        CHECK(light.power().b == Approx(pi * 2.0 * 3.0).epsilon(1e-6));
    }
    // Bounds (-1, -2, -3) to (3, 2, 1): bounding sphere radius |(2, 2, 2)|, r^2 = 12.
    Bounds3 bounds;
    bounds.expand(Vec3(-1.0f, -2.0f, -3.0f));
    bounds.expand(Vec3(3.0f, 2.0f, 1.0f));
    SECTION("constant environment: pi r^2 4 pi L after preprocess") {
        ConstantEnvironmentLight light(Spectrum(0.25f, 0.5f, 1.0f));
        light.preprocess(bounds);
        CHECK(light.power().g == Approx(pi * 12.0 * 4.0 * pi * 0.5).epsilon(1e-6));
    }
    SECTION("directional: E pi r^2 after preprocess") {
        DirectionalLight light(Vec3(0.0f, -1.0f, 0.0f), Spectrum(2.0f));
        light.preprocess(bounds);
        CHECK(light.power().r == Approx(2.0 * pi * 12.0).epsilon(1e-6));
    }
    SECTION("an environment map of a constant image: the constant environment's power") {
        // Each row's solid angle is exact; the sum of 8 rows of 16 pixels rounds about 30 times.
        ConstantEnvironmentLight constant(Spectrum(0.25f, 0.5f, 1.0f));
        EnvironmentMapLight map(Image(16, 8, Spectrum(0.25f, 0.5f, 1.0f)), Spectrum(1.0f), testing::rotation(20.0f, Vec3(1.0f)));
        constant.preprocess(bounds);
        map.preprocess(bounds);
        for (int c = 0; c < 3; ++c) CHECK(map.power()[c] == Approx(constant.power()[c]).epsilon(40.0 * float_epsilon));
        // The scale multiplies it.
        EnvironmentMapLight scaled(Image(16, 8, Spectrum(0.25f, 0.5f, 1.0f)), Spectrum(3.0f), Mat3(1.0f));
        scaled.preprocess(bounds);
        CHECK(scaled.power().g == Approx(3.0 * constant.power().g).epsilon(40.0 * float_epsilon));
    }
}

TEST_CASE("every light's pdf_le is the pair of densities its sample_le reports", "[unit][lights][ch03][ch04]") {
    // Bidirectional path tracing (chapter 04) needs a light's emission densities for paths that
    // another strategy made; MIS weights stay unbiased whatever they are, so only this test sees
    // a pdf_le that disagrees with sample_le. 500 rays per light; delta parts are 0 by contract
    // (a point or spot light's position, a directional light's direction).
    Bounds3 bounds;
    bounds.expand(Vec3(-1.0f, -2.0f, -3.0f));
    bounds.expand(Vec3(3.0f, 2.0f, 1.0f));
    TriangleMesh mesh;
    mesh.positions = {Vec3(-1.0f, -1.0f, 0.5f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.2f)};
    mesh.triangles = {{0u, 1u, 2u}};
    TriangleLight triangle(mesh, 0, Spectrum(1.0f));
    PointLight point(Vec3(0.5f, 1.0f, -0.5f), Spectrum(2.0f));
    SpotLight spot(Vec3(0.0f), glm::normalize(Vec3(0.3f, -1.0f, 0.2f)), Spectrum(2.0f),
                   static_cast<float>(std::cos(40.0 * pi / 180.0)), static_cast<float>(std::cos(15.0 * pi / 180.0)));
    DirectionalLight directional(glm::normalize(Vec3(0.2f, -1.0f, 0.4f)), Spectrum(2.0f));
    ConstantEnvironmentLight constant(Spectrum(0.5f));
    Image map_image(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) map_image.at(x, y) = Spectrum(0.1f + static_cast<float>(x + 2 * y));
    EnvironmentMapLight map(map_image, Spectrum(1.0f), testing::rotation(30.0f, Vec3(1.0f, 2.0f, 0.5f)));
    const std::vector<std::pair<const char*, Light*>> lights = {{"triangle", &triangle}, {"point", &point},
                                                                {"spot", &spot},         {"directional", &directional},
                                                                {"constant", &constant}, {"map", &map}};
    PCG32 random(17, 5);
    for (const auto& [name, light] : lights) {
        light->preprocess(bounds);
        const bool delta_position = light->type() == LightType::DeltaPosition;
        const bool delta_direction = light->type() == LightType::DeltaDirection;
        int checked = 0;
        for (int i = 0; i < 500; ++i) {
            const Vec2 u_position(random.next_float(), random.next_float());
            const Vec2 u_direction(random.next_float(), random.next_float());
            const std::optional<LightEmissionSample> emission = light->sample_le(u_position, u_direction);
            if (!emission) continue;
            ++checked;
            const EmissionDensity density = light->pdf_le(emission->ray, emission->normal);
            INFO(name << ", ray " << i);
            if (delta_position) CHECK(density.position == 0.0f);
            else CHECK(density.position == Approx(emission->pdf_position).epsilon(1e-5));
            if (delta_direction) {
                CHECK(density.direction == 0.0f);
            } else {
                // The map's density depends on the direction's pixel and on sin theta (see
                // pdf_li_relative_error); the others are exact up to a few roundings.
                const double tolerance = light->type() == LightType::Infinite ? 1e-3 : 1e-5;
                CHECK(density.direction == Approx(emission->pdf_direction).epsilon(tolerance));
            }
        }
        INFO(name);
        CHECK(checked >= 450);
    }
}
