// Grading tests of chapter 10's exercises. ch10/cluster-importance is checked against values
// worked out by hand from the bound (book chapter 10): a point light seen head on, at 60 degrees
// and at grazing incidence; a small one-sided light seen from its front, from 45 degrees and from
// behind; a point inside a cluster; a spot-like cone from inside and outside its reach.
// ch10/tree-path-probability is checked against the probabilities sample() reports for the
// lights it chooses (its own walk), beside-the-tree lights and lights never reached.
// Deterministic: no statistical test in this file.
#include "freezeray/ch03/area_light.hpp"
#include "freezeray/ch03/environment_light.hpp"
#include "freezeray/ch03/point_light.hpp"
#include "freezeray/ch10/bvh_light_sampler.hpp"
#include "freezeray/ch10/light_bounds.hpp"
#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch10;

namespace {

LightBounds cluster(const Vec3& low, const Vec3& high, const Vec3& w, float phi, float cos_theta_o, float cos_theta_e) {
    LightBounds b;
    b.box.expand(low);
    b.box.expand(high);
    b.w = w;
    b.phi = phi;
    b.cos_theta_o = cos_theta_o;
    b.cos_theta_e = cos_theta_e;
    return b;
}

constexpr double relative = 1e-5;

}  // namespace

TEST_CASE("ch10/cluster-importance", "[exercise]") {
    // A point light of phi 2 at the origin: every direction (theta_o = pi), no extent.
    const LightBounds point_light = cluster(Vec3(0.0f), Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), 2.0f, -1.0f, std::cos(Pi / 2.0f));
    // Head on from 2 away: 2 * 1 / 4, with or without the normal.
    REQUIRE(importance(point_light, {Vec3(0.0f, 0.0f, 2.0f), Vec3(0.0f, 0.0f, -1.0f)}) == Approx(0.5).epsilon(relative));
    CHECK(importance(point_light, {Vec3(0.0f, 0.0f, 2.0f), Vec3(0.0f)}) == Approx(0.5).epsilon(relative));
    // The normal at 60 degrees to the light: |cos| 1/2. The normal's sign does not matter.
    const Vec3 tilted(std::sin(Pi / 3.0f), 0.0f, std::cos(Pi / 3.0f));
    CHECK(importance(point_light, {Vec3(0.0f, 0.0f, 2.0f), tilted}) == Approx(0.25).epsilon(relative));
    CHECK(importance(point_light, {Vec3(0.0f, 0.0f, 2.0f), -tilted}) == Approx(0.25).epsilon(relative));
    // The light in the surface's plane: the receiver factor stays at its floor.
    CHECK(importance(point_light, {Vec3(2.0f, 0.0f, 0.0f), Vec3(0.0f, 0.0f, 1.0f)}) ==
          Approx(0.5 * ReceiverFloor).epsilon(relative));

    // A small one-sided light (half-diagonal 0.01 sqrt 2) of phi 3 facing +z.
    const float h = 0.01f;
    const LightBounds small = cluster(Vec3(-h, -h, 0.0f), Vec3(h, h, 0.0f), Vec3(0.0f, 0.0f, 1.0f), 3.0f, 1.0f, std::cos(Pi / 2.0f));
    CHECK(importance(small, {Vec3(0.0f, 0.0f, 10.0f), Vec3(0.0f)}) == Approx(0.03).epsilon(relative));
    // From 45 degrees, 10 away: the emitter cosine is cos(pi/4 - theta_b), theta_b the angle the
    // box's bounding sphere subtends.
    const double theta_b = std::asin(std::sqrt(2.0) * h / 10.0);
    const float s = 10.0f / std::sqrt(2.0f);
    CHECK(importance(small, {Vec3(s, 0.0f, s), Vec3(0.0f)}) == Approx(3.0 * std::cos(Pi / 4.0 - theta_b) / 100.0).epsilon(relative));
    // From behind: nothing.
    CHECK(importance(small, {Vec3(0.0f, 0.0f, -10.0f), Vec3(0.0f, 0.0f, 1.0f)}) == 0.0f);
    CHECK(importance(small, {Vec3(3.0f, 1.0f, -0.5f), Vec3(0.0f)}) == 0.0f);

    // Inside a cluster's bounding sphere every direction may come from it: phi over the squared
    // half-diagonal (3), whatever the normal.
    const LightBounds big = cluster(Vec3(-1.0f), Vec3(1.0f), Vec3(0.0f, 0.0f, 1.0f), 5.0f, 1.0f, std::cos(Pi / 2.0f));
    CHECK(importance(big, {Vec3(0.5f, 0.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f)}) == Approx(5.0 / 3.0).epsilon(relative));
    CHECK(importance(big, {Vec3(0.0f, 0.0f, -0.9f), Vec3(0.0f)}) == Approx(5.0 / 3.0).epsilon(relative));

    // A spot-like cone, full within 20 degrees, reaching 15 degrees further, of a point source:
    // at 30 degrees off its axis 10 away, cos 10 degrees; at 60 degrees (25 beyond) nothing.
    const float degree = Pi / 180.0f;
    const LightBounds spot = cluster(Vec3(0.0f), Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), 4.0f, std::cos(20.0f * degree), std::cos(15.0f * degree));
    const Vec3 at_30(10.0f * std::sin(30.0f * degree), 0.0f, 10.0f * std::cos(30.0f * degree));
    const Vec3 at_60(10.0f * std::sin(60.0f * degree), 0.0f, 10.0f * std::cos(60.0f * degree));
    CHECK(importance(spot, {at_30, Vec3(0.0f)}) == Approx(4.0 * std::cos(10.0 * Pi / 180.0) / 100.0).epsilon(relative));
    CHECK(importance(spot, {at_60, Vec3(0.0f)}) == 0.0f);
    CHECK(importance(spot, {Vec3(0.0f, 0.0f, 10.0f), Vec3(0.0f)}) == Approx(0.04).epsilon(relative));

    // A cluster of no power sends nothing.
    const LightBounds dark = cluster(Vec3(0.0f), Vec3(1.0f), Vec3(0.0f, 0.0f, 1.0f), 0.0f, -1.0f, 0.0f);
    CHECK(importance(dark, {Vec3(5.0f), Vec3(0.0f)}) == 0.0f);
}

TEST_CASE("ch10/tree-path-probability", "[exercise]") {
    // 60 small triangles facing up (+y) between y = 0 and 1, two point lights, a dark one and a
    // constant environment.
    TriangleMesh mesh;
    PCG32 random(5, 1);
    for (int i = 0; i < 60; ++i) {
        const Vec3 c(20.0f * random.next_float() - 10.0f, random.next_float(), 20.0f * random.next_float() - 10.0f);
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(c);
        mesh.positions.push_back(c + Vec3(0.3f, 0.0f, 0.0f));  // wound to face +y
        mesh.positions.push_back(c + Vec3(0.0f, 0.0f, -0.3f));
        mesh.triangles.push_back({base, base + 1, base + 2});
    }
    std::vector<std::unique_ptr<Light>> lights;
    for (std::uint32_t i = 0; i < 60; ++i)
        lights.push_back(std::make_unique<ch03::TriangleLight>(mesh, i, Spectrum(1.0f + 10.0f * random.next_float())));
    lights.push_back(std::make_unique<ch03::PointLight>(Vec3(-4.0f, 3.0f, 2.0f), Spectrum(5.0f)));
    lights.push_back(std::make_unique<ch03::PointLight>(Vec3(6.0f, 2.0f, -1.0f), Spectrum(1.0f)));
    lights.push_back(std::make_unique<ch03::PointLight>(Vec3(0.0f), Spectrum(0.0f)));  // dark
    lights.push_back(std::make_unique<ch03::ConstantEnvironmentLight>(Spectrum(1.0f)));
    for (std::size_t i = 0; i < lights.size(); ++i) lights[i]->index = static_cast<std::uint32_t>(i);
    const BvhLightSampler sampler(lights);
    REQUIRE(sampler.infinite_probability() == 0.5f);

    const ShadingPoint above{Vec3(1.0f, 4.0f, 1.0f), Vec3(0.0f, 1.0f, 0.0f)};
    REQUIRE(sampler.probability(above, *lights[63]) == 0.5f);  // the environment: half, beside the tree
    CHECK(sampler.probability(above, *lights[62]) == 0.0f);    // the dark light is not in the tree
    // Every choice's reported probability, at points above, among and below the triangles.
    for (int k = 0; k < 300; ++k) {
        const ShadingPoint point{Vec3(24.0f * random.next_float() - 12.0f, 8.0f * random.next_float() - 3.0f,
                                      24.0f * random.next_float() - 12.0f),
                                 k % 3 == 0 ? Vec3(0.0f) : glm::normalize(Vec3(random.next_float() - 0.5f, 1.0f, 0.2f))};
        for (int j = 0; j < 20; ++j) {
            const std::optional<LightChoice> choice = sampler.sample(point, random.next_float());
            if (!choice) continue;
            INFO("light " << choice->light->index << " at point (" << point.position.x << ", " << point.position.y << ", "
                          << point.position.z << ")");
            CHECK(sampler.probability(point, *choice->light) == choice->probability);
        }
    }
    // Below every triangle, far from the point lights' reach nothing stops them: the triangles are
    // never chosen there, the point lights are.
    const ShadingPoint below{Vec3(0.0f, -20.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};
    for (int i = 0; i < 60; ++i) CHECK(sampler.probability(below, *lights[static_cast<std::size_t>(i)]) == 0.0f);
    CHECK(sampler.probability(below, *lights[60]) > 0.0f);
}
