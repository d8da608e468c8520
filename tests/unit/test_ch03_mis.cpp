// Chapter 03's light selection and MIS weights, checked exactly: FixedLightSampler's probabilities
// by power and uniform, and the power and balance heuristics (Veach 1997, eqs. 9.4 and 9.13),
// whose weights of the two strategies for one direction must sum to one (Veach's condition for
// an unbiased combination, eq. 9.3), also on a real triangle light and Lambertian surface.
// Deterministic: no statistical test in this file.
#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/ch03/area_light.hpp"
#include "freezeray/ch03/fixed_light_sampler.hpp"
#include "freezeray/ch03/mis.hpp"
#include "freezeray/ch03/point_light.hpp"
#include "freezeray/ch03/spot_light.hpp"
#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch03;

namespace {

constexpr double float_epsilon = 0x1p-24;

// Each heuristic is a ratio, a square, a sum and a division: 4 roundings; two weights and their
// sum make at most 9, 5.4e-7. Allowed: 1e-6.
constexpr double weight_sum_tolerance = 1e-6;

TriangleMesh emitter_mesh() {
    TriangleMesh mesh;
    mesh.positions = {Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};  // faces +z
    mesh.triangles = {{0u, 1u, 2u}};
    return mesh;
}

// Lights as a scene holds them, with their index set as load_scene does.
void number(std::vector<std::unique_ptr<Light>>& lights) {
    for (std::size_t i = 0; i < lights.size(); ++i) lights[i]->index = static_cast<std::uint32_t>(i);
}

}  // namespace

TEST_CASE("the light sampler chooses by power, never a dark light, and uniformly when asked", "[unit][lights][ch03]") {
    const TriangleMesh mesh = emitter_mesh();
    std::vector<std::unique_ptr<Light>> lights;
    lights.push_back(std::make_unique<PointLight>(Vec3(0.0f), Spectrum(1.0f)));                // 4 pi
    lights.push_back(std::make_unique<PointLight>(Vec3(1.0f), Spectrum(0.0f)));                // dark
    lights.push_back(std::make_unique<TriangleLight>(mesh, 0, Spectrum(3.0f)));                 // pi 2 3 = 6 pi
    lights.push_back(std::make_unique<SpotLight>(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), Spectrum(5.0f), 0.0f, 1.0f));
    number(lights);
    // The spot light: cone 90 degrees, all of it falloff band: 2 pi 5 (0 + 1/2) = 5 pi.
    const std::vector<double> power{4.0, 0.0, 6.0, 5.0};  // in units of pi
    const double total = 15.0;

    const FixedLightSampler by_power(lights, LightSelection::Power);
    for (std::size_t i = 0; i < lights.size(); ++i)
        CHECK(by_power.probability(*lights[i]) == Approx(power[i] / total).epsilon(8.0 * float_epsilon).margin(1e-12));
    // A grid of u: the dark light never comes, each choice reports its probability, and each light
    // takes its probability's share of the grid (within the grid's step, 1e-5).
    std::vector<int> chosen(lights.size(), 0);
    const int n = 100000;
    for (int k = 0; k < n; ++k) {
        const auto choice = by_power.sample(static_cast<float>(k) / n);
        REQUIRE(choice);
        REQUIRE(choice->light != lights[1].get());
        REQUIRE(choice->probability == by_power.probability(*choice->light));
        ++chosen[choice->light->index];
    }
    for (std::size_t i = 0; i < lights.size(); ++i) CHECK(chosen[i] / double(n) == Approx(power[i] / total).margin(2e-5));

    const FixedLightSampler uniform(lights, LightSelection::Uniform);
    for (const auto& light : lights) CHECK(uniform.probability(*light) == 0.25f);
    CHECK(uniform.sample(0.3f)->light == lights[1].get());  // even the dark one
    // Light i takes u in [i / n, (i + 1) / n), the last one up to the float just below 1.
    for (int i = 0; i < 4; ++i) {
        CHECK(uniform.sample(0.25f * static_cast<float>(i))->light == lights[static_cast<std::size_t>(i)].get());
        CHECK(uniform.sample(std::nextafter(0.25f * static_cast<float>(i + 1), 0.0f))->light == lights[static_cast<std::size_t>(i)].get());
        CHECK(uniform.sample(0.25f * static_cast<float>(i))->probability == 0.25f);
    }

    // Every light dark: uniform, rather than dividing by zero.
    std::vector<std::unique_ptr<Light>> dark;
    dark.push_back(std::make_unique<PointLight>(Vec3(0.0f), Spectrum(0.0f)));
    dark.push_back(std::make_unique<TriangleLight>(mesh, 0, Spectrum(0.0f)));
    number(dark);
    const FixedLightSampler fallback(dark, LightSelection::Power);
    CHECK(fallback.probability(*dark[0]) == 0.5f);
    CHECK(fallback.sample(0.75f)->light == dark[1].get());

    // No light at all: nothing to choose.
    const std::vector<std::unique_ptr<Light>> none;
    const FixedLightSampler empty(none, LightSelection::Power);
    CHECK_FALSE(empty.sample(0.5f));
}

TEST_CASE("the power and balance heuristics: exact values", "[unit][mis][ch03]") {
    // Veach 1997, eq. 9.13 (beta = 2) and eq. 9.4.
    CHECK(power_heuristic(1, 1.0f, 1, 1.0f) == 0.5f);
    CHECK(power_heuristic(1, 3.0f, 1, 1.0f) == Approx(0.9f).epsilon(4 * float_epsilon));
    CHECK(power_heuristic(1, 1.0f, 1, 3.0f) == Approx(0.1f).epsilon(4 * float_epsilon));
    CHECK(power_heuristic(2, 1.0f, 1, 1.0f) == Approx(0.8f).epsilon(4 * float_epsilon));  // n_f p_f = 2
    CHECK(power_heuristic(1, 1.0f, 3, 1.0f) == Approx(0.1f).epsilon(4 * float_epsilon));
    CHECK(balance_heuristic(1, 3.0f, 1, 1.0f) == Approx(0.75f).epsilon(4 * float_epsilon));
    CHECK(balance_heuristic(2, 1.0f, 1, 1.0f) == Approx(2.0f / 3.0f).epsilon(4 * float_epsilon));
    // A strategy that cannot produce the direction gets nothing, the other everything.
    CHECK(power_heuristic(1, 0.0f, 1, 2.0f) == 0.0f);
    CHECK(power_heuristic(1, 2.0f, 1, 0.0f) == 1.0f);
    CHECK(balance_heuristic(1, 0.0f, 1, 2.0f) == 0.0f);
    CHECK(balance_heuristic(1, 2.0f, 1, 0.0f) == 1.0f);
    CHECK(mis_weight(MisHeuristic::Power, 3.0f, 1.0f) == power_heuristic(1, 3.0f, 1, 1.0f));
    CHECK(mis_weight(MisHeuristic::Balance, 3.0f, 1.0f) == balance_heuristic(1, 3.0f, 1, 1.0f));
}

TEST_CASE("the two strategies' weights sum to one, for densities from 1e-30 to 1e30", "[unit][mis][ch03]") {
    // Where (n p)^2 would overflow or underflow in float, the weights must stay finite, in
    // [0, 1], and still sum to one.
    PCG32 random(21, 5);
    std::vector<std::pair<float, float>> pairs{{1e-30f, 1e30f}, {1e30f, 1e-30f}, {1e30f, 1e30f}, {1e-30f, 1e-30f},
                                               {1e20f, 1e19f}, {3e-20f, 1e-19f}, {1.0f, 1e30f}};
    for (int i = 0; i < 100000; ++i) {
        const auto log_uniform = [&] { return static_cast<float>(std::pow(10.0, 60.0 * random.next_float() - 30.0)); };
        pairs.emplace_back(log_uniform(), log_uniform());
    }
    for (const auto& [f, g] : pairs) {
        INFO("p_f = " << f << ", p_g = " << g);
        for (const MisHeuristic h : {MisHeuristic::Power, MisHeuristic::Balance}) {
            const float w_f = mis_weight(h, f, g), w_g = mis_weight(h, g, f);
            REQUIRE(std::isfinite(w_f));
            REQUIRE(std::isfinite(w_g));
            REQUIRE((w_f >= 0.0f && w_f <= 1.0f && w_g >= 0.0f && w_g <= 1.0f));
            REQUIRE(std::abs(double(w_f) + double(w_g) - 1.0) <= weight_sum_tolerance);
        }
        // With sample counts: n_f = 2, n_g = 3.
        REQUIRE(std::abs(double(power_heuristic(2, f, 3, g)) + power_heuristic(3, g, 2, f) - 1.0) <= weight_sum_tolerance);
    }
}

TEST_CASE("MIS weights of light and BSDF sampling sum to one on a triangle light over a Lambertian surface",
          "[unit][mis][ch03]") {
    // As pt-mis weighs them: a light sample gets w(p_light, bsdf.pdf), the same direction found
    // by BSDF sampling gets w(p_bsdf, light.pdf_li). They sum to one only if sample_li's density
    // is pdf_li's and the BSDF sample's is bsdf.pdf's. w changes by at most 0.5 (power) or 0.25
    // (balance) times the relative difference of its two densities (the largest slope of
    // 1 / (1 + r^2) and 1 / (1 + r) in ln r); the two paths to each density differ by a few
    // roundings (distance from the sampled point, from the ray's hit; cosine unchanged), under
    // 1e-5 relative, so 1e-5 bounds the sum's error with room to spare.
    const TriangleMesh mesh = emitter_mesh();
    const TriangleLight light(mesh, 0, Spectrum(1.0f));
    const ch02::CosineLambertianBSDF bsdf(Spectrum(0.7f));
    constexpr double tolerance = 1e-5;
    // Surface points above the light, facing it more or less; one close, one grazing.
    struct Case {
        Vec3 position, normal;
    };
    for (const Case& c : {Case{Vec3(0.2f, -0.1f, 1.5f), glm::normalize(Vec3(-0.2f, 0.1f, -1.0f))},
                          Case{Vec3(-0.5f, 0.3f, 0.2f), glm::normalize(Vec3(0.3f, 0.0f, -1.0f))},
                          Case{Vec3(0.0f, -3.0f, 0.3f), glm::normalize(Vec3(0.0f, 1.0f, -0.2f))}}) {
        const Frame frame(c.normal);
        const Vec3 wo = glm::normalize(Vec3(0.3f, -0.2f, 1.0f));  // local, above the surface
        PCG32 random(9, 4);
        int light_samples = 0, bsdf_hits = 0;
        for (int i = 0; i < 20000; ++i) {
            const auto s = light.sample_li(c.position, Vec2(random.next_float(), random.next_float()));
            REQUIRE(s);
            const Vec3 wi = frame.to_local(s->wi);
            const float pdf_bsdf = bsdf.pdf(wo, wi);
            if (pdf_bsdf <= 0.0f) continue;  // the light behind the surface's horizon
            ++light_samples;
            const float pdf_light = light.pdf_li(c.position, s->wi);
            INFO("light sample " << i << ": sample_li pdf " << s->pdf << ", pdf_li " << pdf_light);
            REQUIRE(pdf_light > 0.0f);
            for (const MisHeuristic h : {MisHeuristic::Power, MisHeuristic::Balance})
                REQUIRE(std::abs(double(mis_weight(h, s->pdf, pdf_bsdf)) + mis_weight(h, pdf_bsdf, pdf_light) - 1.0) <=
                        tolerance);
        }
        for (int i = 0; i < 20000; ++i) {
            const auto b = bsdf.sample(wo, Vec2(random.next_float(), random.next_float()), random.next_float());
            REQUIRE(b);
            const Vec3 wi = frame.to_world(b->wi);
            const float pdf_light = light.pdf_li(c.position, wi);
            if (pdf_light <= 0.0f) continue;  // misses the light
            ++bsdf_hits;
            INFO("BSDF sample " << i << ": sample pdf " << b->pdf << ", pdf " << bsdf.pdf(wo, b->wi));
            for (const MisHeuristic h : {MisHeuristic::Power, MisHeuristic::Balance})
                REQUIRE(std::abs(double(mis_weight(h, b->pdf, pdf_light)) + mis_weight(h, pdf_light, bsdf.pdf(wo, b->wi)) -
                                 1.0) <= tolerance);
        }
        // The checks above ran on enough directions to mean something.
        CHECK(light_samples > 1000);
        CHECK(bsdf_hits > 100);
    }
}
