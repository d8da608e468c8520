// Grading tests of chapter 10's exercises. ch10/cluster-importance is checked against values
// worked out by hand from the bound (book chapter 10): a point light seen head on, at 60 degrees
// and at grazing incidence; a small one-sided light seen from its front, from 45 degrees and from
// behind; a point inside a cluster; a spot-like cone from inside and outside its reach; and lane
// by lane (four clusters in one group give what each gives alone, an empty lane 0).
// ch10/tree-path-probability is checked against the probabilities sample() reports for the
// lights it chooses (its own walk), beside-the-tree lights and lights never reached.
// ch10/tree-walk is checked against the probability of every light found by enumerating the
// tree (each choice's reported probability, exactly) and by a chi-square test of which lights
// 200,000 walks choose at each of 4 points (false-failure rate at most 1e-6 over the four).
// The other tests are deterministic.
#include "chi_square.hpp"
#include "statistics.hpp"

#include "freezeray/ch03/area_light.hpp"
#include "freezeray/ch03/environment_light.hpp"
#include "freezeray/ch03/point_light.hpp"
#include "freezeray/ch10/bvh_light_sampler.hpp"
#include "freezeray/ch10/light_bounds.hpp"
#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
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

    // Lane by lane: four different clusters in one group give, each in its lane, what each gives
    // alone (in lane 0, with the other lanes empty), to the bit; an empty lane gives 0.
    const LightBounds groups[2][LaneCount] = {{point_light, small, big, spot}, {spot, dark, small, point_light}};
    const ShadingPoint points[] = {{Vec3(0.0f, 0.0f, 2.0f), tilted}, {Vec3(s, 0.0f, s), Vec3(0.0f)}, {Vec3(0.5f, 0.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f)},
                                   {at_30, Vec3(0.0f, 1.0f, 0.0f)}, {Vec3(3.0f, 1.0f, -0.5f), Vec3(0.0f)}};
    for (const auto& members : groups) {
        LightClusterGroup group;
        for (int lane = 0; lane < LaneCount; ++lane) group.set(lane, members[lane]);
        for (const ShadingPoint& point : points) {
            const Lanes together = importance(group, point);
            for (int lane = 0; lane < LaneCount; ++lane) {
                INFO("lane " << lane << ", point (" << point.position.x << ", " << point.position.y << ", " << point.position.z << ")");
                CHECK(together[lane] == importance(members[lane], point));
            }
        }
    }
    LightClusterGroup one;
    one.set(1, small);
    const Lanes alone = importance(one, {Vec3(0.0f, 0.0f, 10.0f), Vec3(0.0f)});
    CHECK(alone[0] == 0.0f);
    CHECK(alone[1] == Approx(0.03).epsilon(relative));
    CHECK(alone[2] == 0.0f);
    CHECK(alone[3] == 0.0f);
}

namespace {

// 60 small triangles facing up (+y) between y = 0 and 1 with random emission (positions and
// emissions drawn from `random`), two point lights, a dark one and a constant environment. The
// mesh outlives the lights that refer to it.
struct LightTreeScene {
    TriangleMesh mesh;
    std::vector<std::unique_ptr<Light>> lights;
};

std::unique_ptr<LightTreeScene> light_tree_scene(PCG32& random) {
    auto scene = std::make_unique<LightTreeScene>();
    for (int i = 0; i < 60; ++i) {
        const Vec3 c(20.0f * random.next_float() - 10.0f, random.next_float(), 20.0f * random.next_float() - 10.0f);
        const auto base = static_cast<std::uint32_t>(scene->mesh.positions.size());
        scene->mesh.positions.push_back(c);
        scene->mesh.positions.push_back(c + Vec3(0.3f, 0.0f, 0.0f));  // wound to face +y
        scene->mesh.positions.push_back(c + Vec3(0.0f, 0.0f, -0.3f));
        scene->mesh.triangles.push_back({base, base + 1, base + 2});
    }
    for (std::uint32_t i = 0; i < 60; ++i)
        scene->lights.push_back(std::make_unique<ch03::TriangleLight>(scene->mesh, i, Spectrum(1.0f + 10.0f * random.next_float())));
    scene->lights.push_back(std::make_unique<ch03::PointLight>(Vec3(-4.0f, 3.0f, 2.0f), Spectrum(5.0f)));
    scene->lights.push_back(std::make_unique<ch03::PointLight>(Vec3(6.0f, 2.0f, -1.0f), Spectrum(1.0f)));
    scene->lights.push_back(std::make_unique<ch03::PointLight>(Vec3(0.0f), Spectrum(0.0f)));  // dark
    scene->lights.push_back(std::make_unique<ch03::ConstantEnvironmentLight>(Spectrum(1.0f)));
    for (std::size_t i = 0; i < scene->lights.size(); ++i) scene->lights[i]->index = static_cast<std::uint32_t>(i);
    return scene;
}

}  // namespace

TEST_CASE("ch10/tree-path-probability", "[exercise]") {
    PCG32 random(5, 1);  // the scene's numbers first, then the points'
    const std::unique_ptr<LightTreeScene> scene = light_tree_scene(random);
    const std::vector<std::unique_ptr<Light>>& lights = scene->lights;
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

namespace {

// The probability of reaching each light from the node `index`, by visiting every branch: the
// children's probabilities from child_probabilities, multiplied from the root down as sample()'s
// comment says; a branch where no child sends light leaves its lights at 0.
void tree_probabilities(const BvhLightSampler& sampler, const ShadingPoint& point, std::uint32_t index, float probability,
                        std::vector<float>& out) {
    const LightTreeNode& node = sampler.nodes()[index];
    const ChildProbabilities p = child_probabilities(node, point);
    if (p[0] < 0.0f) return;
    for (int i = 0; i < static_cast<int>(node.child_count); ++i) {
        const float q = probability * p[static_cast<std::size_t>(i)];
        if (node.child_is_light(i)) out[node.child_index(i)] = q;
        else tree_probabilities(sampler, point, node.child_index(i), q, out);
    }
}

}  // namespace

TEST_CASE("ch10/tree-walk", "[exercise]") {
    PCG32 scene_random(17, 1);
    const std::unique_ptr<LightTreeScene> scene = light_tree_scene(scene_random);
    const std::vector<std::unique_ptr<Light>>& lights = scene->lights;
    const BvhLightSampler sampler(lights);
    REQUIRE(sampler.infinite_probability() == 0.5f);
    int in_tree = 0;
    for (const LightTreeNode& node : sampler.nodes())
        for (int i = 0; i < static_cast<int>(node.child_count); ++i) in_tree += node.child_is_light(i) ? 1 : 0;
    REQUIRE(in_tree == 62);  // the 62 lights with power, each once
    const float tree_share = 1.0f - sampler.infinite_probability();
    const ShadingPoint first{Vec3(1.0f, 4.0f, 1.0f), Vec3(0.0f, 1.0f, 0.0f)};
    sampler.sample(first, 0.75f);  // the walk itself first (in a student's copy, its stub speaks)

    // Exactly: each choice's reported probability is the product along its path.
    PCG32 random(23, 4);
    auto random_point = [&](int k) {
        return ShadingPoint{Vec3(24.0f * random.next_float() - 12.0f, 8.0f * random.next_float() - 3.0f, 24.0f * random.next_float() - 12.0f),
                            k % 3 == 0 ? Vec3(0.0f) : glm::normalize(Vec3(random.next_float() - 0.5f, 1.0f, 0.2f))};
    };
    int choices = 0, nothing = 0;
    for (int k = 0; k < 300; ++k) {
        const ShadingPoint point = random_point(k);
        std::vector<float> expected(lights.size(), 0.0f);
        tree_probabilities(sampler, point, 0, tree_share, expected);
        for (int j = 0; j < 20; ++j) {
            const float u = 0.5f + 0.5f * random.next_float();  // in the tree's share
            const std::optional<LightChoice> choice = sampler.sample(point, u);
            INFO("point (" << point.position.x << ", " << point.position.y << ", " << point.position.z << "), u = " << u);
            if (!choice) {
                ++nothing;  // a branch that sends no light here
                continue;
            }
            ++choices;
            REQUIRE(choice->light != nullptr);
            INFO("light " << choice->light->index << ": its path's probability is " << expected[choice->light->index]);
            CHECK(choice->probability == expected[choice->light->index]);
            CHECK(expected[choice->light->index] > 0.0f);
        }
    }
    CHECK(choices > 4000);  // of 6000 walks; points below the triangles reach only the point lights
    CHECK(nothing < choices);

    // In proportion: which light 200,000 walks choose (u uniform in [0, 1), the environment's half
    // included), against those probabilities. Each of the four points is tested at 1e-6 / 4.
    const std::vector<ShadingPoint> points{{Vec3(0.0f, 4.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)},
                                           {Vec3(-8.0f, 0.5f, 6.0f), Vec3(0.0f)},
                                           {Vec3(5.0f, 1.5f, -3.0f), glm::normalize(Vec3(1.0f, 1.0f, 0.0f))},
                                           {Vec3(9.0f, -2.0f, 9.0f), Vec3(0.0f, 1.0f, 0.0f)}};
    constexpr int walks = 200000;
    for (const ShadingPoint& point : points) {
        std::vector<float> probabilities(lights.size(), 0.0f);
        tree_probabilities(sampler, point, 0, tree_share, probabilities);
        probabilities[63] = sampler.infinite_probability();  // the environment, beside the tree
        const std::size_t none = lights.size();              // the cell of walks that choose nothing
        std::vector<double> observed(none + 1, 0.0), expected(none + 1, 0.0);
        double sum = 0.0;
        for (std::size_t i = 0; i < lights.size(); ++i) {
            expected[i] = walks * static_cast<double>(probabilities[i]);
            sum += probabilities[i];
        }
        expected[none] = walks * std::max(0.0, 1.0 - sum);
        for (int k = 0; k < walks; ++k) {
            const std::optional<LightChoice> choice = sampler.sample(point, random.next_float());
            observed[choice ? choice->light->index : none] += 1.0;
        }
        std::uint64_t in_empty_cells = 0;  // chosen where its probability is 0
        const auto [statistic, cells] = stats::pooled_statistic(observed, expected, 5.0, in_empty_cells);
        const double p_value = stats::chi_square_survival(statistic, cells - 1);
        INFO("point (" << point.position.x << ", " << point.position.y << ", " << point.position.z << "): chi^2 = " << statistic
                       << " over " << cells << " cells, p = " << p_value << "; " << in_empty_cells
                       << " walks chose a light whose probability is 0");
        CHECK(in_empty_cells == 0u);
        CHECK(cells >= 3);  // below the triangles: the two point lights and the environment
        CHECK(p_value > stats::exercise_test_alpha / 4.0);
    }
}
