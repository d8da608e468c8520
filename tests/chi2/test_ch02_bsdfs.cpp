// Chapter 02's BSDFs: every sampling routine against its own pdf (chi-square goodness of fit on
// the sphere of directions wi), for incident directions from normal to grazing (cos 0.01), from
// both sides, roughness from 0.1 to 1 (alpha = roughness^2), isotropic and anisotropic.
//
// A routine that sometimes returns nothing (a microfacet reflection that leaves below the
// surface) has a pdf integrating to its success probability; the harness compares the failures
// with 1 minus the pdf's integral as one more cell, so no expected integral is given for those.
// Delta lobes (smooth coatings, mixtures with glass) have no density on the sphere: their samples
// are left out, and the pdf then integrates to the probability of the non-delta lobes, which
// the test states. Smoother surfaces (roughness below 0.1, effectively smooth below 0.03) are
// checked exactly in tests/unit/test_ch02_bsdfs.cpp.
#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/ch02/microfacet.hpp"
#include "freezeray/ch02/mix_bsdf.hpp"
#include "freezeray/ch02/plastic.hpp"
#include "freezeray/ch02/rough_conductor.hpp"
#include "freezeray/ch02/rough_dielectric.hpp"
#include "freezeray/ch02/smooth_dielectric.hpp"

#include "chi_square.hpp"
#include "evidence.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

using namespace freezeray;
using namespace freezeray::ch02;

namespace {

// A unit direction at the given cos(theta) and azimuth phi.
Vec3 direction(float cos_theta, float phi) {
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

// Incident directions: near the normal, oblique, grazing (cos 0.01); `below` flips them inside.
std::vector<Vec3> incident_directions(bool below) {
    std::vector<Vec3> directions{direction(0.95f, 0.3f), direction(0.5f, 2.0f), direction(0.01f, 4.0f)};
    if (below)
        for (Vec3& w : directions) w.z = -w.z;
    return directions;
}

TrowbridgeReitz isotropic(float roughness) {
    const float alpha = TrowbridgeReitz::roughness_to_alpha(roughness);
    return TrowbridgeReitz(alpha, alpha);
}

// "name-r0.3": a test's name with its roughness.
std::string with_roughness(const std::string& name, float roughness) {
    std::ostringstream out;
    out << name << "-r" << roughness;
    return out.str();
}

std::string describe(const std::string& name, const Vec3& wo) {
    std::ostringstream out;
    out << name << ", wo = (" << wo.x << ", " << wo.y << ", " << wo.z << ")";
    return out.str();
}

struct Chi2Request {
    std::uint64_t sample_count = 200'000;
    int resolution = 10;
    bool exclude_delta = false;                   // leave delta-lobe samples out
    std::optional<double> expected_pdf_integral;  // none: sampling may fail
};

// The chi-square test of bsdf.sample(wo, ...) against bsdf.pdf(wo, .) on the sphere; fails the
// test case with the harness's message and writes the evidence.
void check_sampling_matches_pdf(const BSDF& bsdf, const Vec3& wo, const std::string& name, const Chi2Request& request) {
    stats::ChiSquareOptions options;
    options.sample_count = request.sample_count;
    options.resolution = request.resolution;
    options.expected_pdf_integral = request.expected_pdf_integral;
    const auto result = stats::chi_square_test(
        stats::Domain::sphere(),
        [&](PCG32& r) -> std::optional<Vec3> {
            const Vec2 u(r.next_float(), r.next_float());
            const auto s = bsdf.sample(wo, u, r.next_float());
            if (!s) return std::nullopt;
            if (request.exclude_delta && has_flag(s->flags, BSDF_Specular)) return std::nullopt;
            return s->wi;
        },
        [&](const Vec3& wi) { return static_cast<double>(bsdf.pdf(wo, wi)); }, options);
    const std::string what = describe(name, wo);
    if (!result.passed) {
        const std::string folder = stats::write_evidence("chi2-" + name, result);
        FAIL(what << "\n" << result.message << "\nevidence: " << folder);
    }
    SUCCEED(what << ": " << result.message);
}

}  // namespace

TEST_CASE("the cosine-weighted Lambertian BSDF's sample matches its pdf on both sides", "[chi2][bsdf][ch02]") {
    const CosineLambertianBSDF bsdf(Spectrum(0.5f));
    Chi2Request request;
    request.expected_pdf_integral = 1.0;
    for (bool below : {false, true})
        for (const Vec3& wo : incident_directions(below))
            check_sampling_matches_pdf(bsdf, wo, "cosine-lambertian", request);
}

TEST_CASE("the rough conductor's visible-normal sampling matches its pdf", "[chi2][bsdf][ch02]") {
    const Spectrum eta(0.2f, 0.9f, 1.1f);
    const Spectrum k(3.9f, 2.5f, 2.4f);
    for (float roughness : {0.3f, 0.6f, 1.0f}) {
        const RoughConductorBSDF bsdf(isotropic(roughness), eta, k);
        for (const Vec3& wo : incident_directions(false))
            check_sampling_matches_pdf(bsdf, wo, with_roughness("rough-conductor", roughness), {});
    }
    // A narrow lobe needs finer cells for the quadrature to see it.
    Chi2Request narrow;
    narrow.resolution = 40;
    narrow.sample_count = 1'000'000;
    for (float roughness : {0.05f, 0.1f}) {
        const RoughConductorBSDF shiny(isotropic(roughness), eta, k);
        check_sampling_matches_pdf(shiny, direction(0.5f, 1.0f), with_roughness("rough-conductor", roughness), narrow);
    }
    // Seen from below, the surface reflects on that side.
    const RoughConductorBSDF below(isotropic(0.5f), eta, k);
    check_sampling_matches_pdf(below, direction(-0.6f, 0.7f), "rough-conductor-below", {});
}

TEST_CASE("the anisotropic rough conductor's sampling matches its pdf", "[chi2][bsdf][ch02]") {
    const TrowbridgeReitz distribution(TrowbridgeReitz::roughness_to_alpha(0.3f),
                                       TrowbridgeReitz::roughness_to_alpha(0.8f));
    const RoughConductorBSDF bsdf(distribution, Spectrum(1.2f), Spectrum(6.0f));
    for (const Vec3& wo : incident_directions(false))
        check_sampling_matches_pdf(bsdf, wo, "rough-conductor-anisotropic", {});
}

TEST_CASE("the rough dielectric's sampling matches its pdf from outside and inside", "[chi2][bsdf][ch02]") {
    for (float roughness : {0.3f, 0.6f, 1.0f}) {
        const RoughDielectricBSDF bsdf(isotropic(roughness), 1.5f);
        for (bool below : {false, true})
            for (const Vec3& wo : incident_directions(below))
                check_sampling_matches_pdf(bsdf, wo, with_roughness("rough-dielectric", roughness), {});
    }
    // Narrow lobes: finer cells from outside. From inside, finer cells make the harness's
    // quadrature slow (45 s at resolution 40: the pdf has edges, total internal reflection and
    // back-facing microfacets, across many cells), so those keep the default cells, where the
    // pdf's integral still matches to 1e-4.
    Chi2Request narrow;
    narrow.resolution = 40;
    narrow.sample_count = 1'000'000;
    const RoughDielectricBSDF frosted(isotropic(0.1f), 1.5f);
    check_sampling_matches_pdf(frosted, direction(0.5f, 1.0f), "rough-dielectric-r0.1", narrow);
    narrow.resolution = 10;
    check_sampling_matches_pdf(frosted, direction(-0.8f, 1.0f), "rough-dielectric-r0.1-inside", narrow);
    check_sampling_matches_pdf(frosted, direction(-0.3f, 1.0f), "rough-dielectric-r0.1-inside", narrow);
}

TEST_CASE("the rough dielectric's sampling matches its pdf: anisotropic, eta < 1", "[chi2][bsdf][ch02]") {
    const TrowbridgeReitz distribution(TrowbridgeReitz::roughness_to_alpha(0.4f),
                                       TrowbridgeReitz::roughness_to_alpha(0.9f));
    const RoughDielectricBSDF anisotropic(distribution, 1.33f);
    check_sampling_matches_pdf(anisotropic, direction(0.7f, 0.5f), "rough-dielectric-anisotropic", {});
    check_sampling_matches_pdf(anisotropic, direction(-0.7f, 2.5f), "rough-dielectric-anisotropic", {});
    // An interface whose outside is the denser medium (an air bubble in water).
    const RoughDielectricBSDF bubble(isotropic(0.5f), 1.0f / 1.33f);
    check_sampling_matches_pdf(bubble, direction(0.6f, 0.2f), "rough-dielectric-eta-below-1", {});
}

TEST_CASE("rough plastic's mixture sampling matches its mixture pdf", "[chi2][bsdf][ch02]") {
    for (float roughness : {0.3f, 0.7f}) {
        const TrowbridgeReitz coating = isotropic(roughness);
        const PlasticBSDF bsdf(Spectrum(0.6f, 0.3f, 0.1f), 1.5f, &coating);
        for (const Vec3& wo : incident_directions(false))
            check_sampling_matches_pdf(bsdf, wo, with_roughness("rough-plastic", roughness), {});
    }
    const TrowbridgeReitz coating = isotropic(0.5f);
    const PlasticBSDF bsdf(Spectrum(0.5f), 1.5f, &coating);
    check_sampling_matches_pdf(bsdf, direction(-0.5f, 1.0f), "rough-plastic-below", {});
}

TEST_CASE("smooth plastic's diffuse samples match its pdf (the delta lobe left out)", "[chi2][bsdf][ch02]") {
    const PlasticBSDF bsdf(Spectrum(0.6f, 0.3f, 0.1f), 1.5f, nullptr);
    for (bool below : {false, true}) {
        for (const Vec3& wo : incident_directions(below)) {
            Chi2Request request;
            request.exclude_delta = true;
            request.expected_pdf_integral = 1.0 - bsdf.specular_probability(wo);
            check_sampling_matches_pdf(bsdf, wo, "smooth-plastic", request);
        }
    }
}

TEST_CASE("MixBSDF's sampling matches its mixture pdf", "[chi2][bsdf][ch02]") {
    const CosineLambertianBSDF diffuse(Spectrum(0.8f));
    const RoughConductorBSDF metal(isotropic(0.4f), Spectrum(0.2f), Spectrum(3.0f));
    const MixBSDF mix(&diffuse, &metal, 0.3f);
    check_sampling_matches_pdf(mix, direction(0.7f, 1.0f), "mix-diffuse-metal", {});
    check_sampling_matches_pdf(mix, direction(-0.2f, 3.0f), "mix-diffuse-metal", {});

    // With a delta component, only the other component's samples have a density: the pdf
    // integrates to its weight.
    const SmoothDielectricBSDF glass(1.5f);
    const MixBSDF with_glass(&glass, &diffuse, 0.25f);
    Chi2Request request;
    request.exclude_delta = true;
    request.expected_pdf_integral = 0.25;
    check_sampling_matches_pdf(with_glass, direction(0.4f, 5.0f), "mix-glass-diffuse", request);
}
