// Every warp of chapter 01's warps.hpp against its own density (chi-square goodness of fit).
#include "freezeray/ch01/lambertian.hpp"
#include "freezeray/ch01/warps.hpp"

#include "chi_square.hpp"
#include "evidence.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;
using namespace freezeray::ch01;

namespace {

void require_passes(const stats::ChiSquareResult& result, const std::string& name) {
    if (!result.passed) {
        const std::string folder = stats::write_evidence(name, result);
        FAIL(result.message << "\nevidence: " << folder);
    }
    SUCCEED(result.message);
}

}  // namespace

TEST_CASE("uniform hemisphere sampling matches its pdf", "[chi2][warps]") {
    const auto result = stats::chi_square_test(
        stats::Domain::hemisphere(),
        [](PCG32& r) -> std::optional<Vec3> { return sample_uniform_hemisphere(Vec2(r.next_float(), r.next_float())); },
        [](const Vec3&) { return static_cast<double>(uniform_hemisphere_pdf()); }, {});
    require_passes(result, "chi2-uniform-hemisphere");
}

TEST_CASE("uniform sphere sampling matches its pdf", "[chi2][warps]") {
    const auto result = stats::chi_square_test(
        stats::Domain::sphere(),
        [](PCG32& r) -> std::optional<Vec3> { return sample_uniform_sphere(Vec2(r.next_float(), r.next_float())); },
        [](const Vec3&) { return static_cast<double>(uniform_sphere_pdf()); }, {});
    require_passes(result, "chi2-uniform-sphere");
}

TEST_CASE("uniform triangle sampling matches its pdf (on the unit square's lower triangle)", "[chi2][warps]") {
    // Barycentrics (b0, b1) of the triangle (0,0), (1,0), (0,1) are points of the unit square
    // below its diagonal, with density 1 / area = 2 there.
    const auto result = stats::chi_square_test(
        stats::Domain::unit_square(),
        [](PCG32& r) -> std::optional<Vec3> {
            const Vec2 b = sample_uniform_triangle(Vec2(r.next_float(), r.next_float()));
            return Vec3(b.x, b.y, 0.0f);
        },
        [](const Vec3& p) { return p.x + p.y <= 1.0f ? 2.0 : 0.0; }, {});
    require_passes(result, "chi2-uniform-triangle");
}

TEST_CASE("the Lambertian BSDF's sample matches its pdf on both sides", "[chi2][bsdf]") {
    const LambertianBSDF bsdf(Spectrum(0.5f));
    for (const Vec3 wo : {glm::normalize(Vec3(0.3f, 0.2f, 1.0f)), glm::normalize(Vec3(0.3f, 0.2f, -1.0f)),
                          glm::normalize(Vec3(1.0f, 0.0f, 0.01f))}) {
        const auto result = stats::chi_square_test(
            stats::Domain::sphere(),
            [&](PCG32& r) -> std::optional<Vec3> {
                const auto s = bsdf.sample(wo, Vec2(r.next_float(), r.next_float()), r.next_float());
                if (!s) return std::nullopt;
                return s->wi;
            },
            [&](const Vec3& wi) { return static_cast<double>(bsdf.pdf(wo, wi)); }, {});
        require_passes(result, "chi2-lambertian");
    }
}
