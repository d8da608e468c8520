// Chapter 02's BSDFs: what every sample promises (weight = f |cos| / pdf with f = eval and
// pdf = pdf()), delta lobes, the fallback of rough models to smooth ones, reciprocity, energy
// conservation, and that nothing returns NaN. Deterministic except the tests named "Monte Carlo",
// which are t-tests at unit_test_alpha (tests/STATISTICS.md).
#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/ch02/fresnel.hpp"
#include "freezeray/ch02/microfacet.hpp"
#include "freezeray/ch02/mirror.hpp"
#include "freezeray/ch02/mix_bsdf.hpp"
#include "freezeray/ch02/plastic.hpp"
#include "freezeray/ch02/rough_conductor.hpp"
#include "freezeray/ch02/rough_dielectric.hpp"
#include "freezeray/ch02/smooth_dielectric.hpp"
#include "freezeray/ch02/specular_conductor.hpp"

#include "chi_square.hpp"
#include "statistics.hpp"

#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch02;

namespace {

Vec3 direction(float cos_theta, float phi) {
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

TrowbridgeReitz isotropic(float roughness) {
    const float alpha = TrowbridgeReitz::roughness_to_alpha(roughness);
    return TrowbridgeReitz(alpha, alpha);
}

// A metal that reflects everything at every angle: its rough version loses only what masking
// and shadowing hide.
const Spectrum perfect_eta(0.0f);
const Spectrum perfect_k(0.0f);

// n(wi side) / n(wo side) for a dielectric of relative index eta (inside below the surface).
float eta_crossed(const Vec3& wo, const Vec3& wi, float eta) {
    if (wo.z * wi.z > 0.0f) return 1.0f;
    return wo.z > 0.0f ? eta : 1.0f / eta;
}

// The directional albedo: the integral of f |cos theta_i| over the sphere (one channel; the
// BSDFs here are grey), by adaptive quadrature. `eta` > 0: a dielectric whose radiance
// scaling 1 / eta'^2 on transmission is removed, so that what is measured is energy.
double albedo_by_quadrature(const BSDF& bsdf, const Vec3& wo, float eta = 0.0f, int resolution = 10) {
    return stats::integrate_over_domain(
        stats::Domain::sphere(),
        [&](const Vec3& wi) {
            const float scale = eta > 0.0f ? eta_crossed(wo, wi, eta) * eta_crossed(wo, wi, eta) : 1.0f;
            return static_cast<double>(bsdf.eval(wo, wi).x) * std::abs(wi.z) * scale;
        },
        resolution);
}

// The weights of `count` samples (0 for a failed sample), with the radiance scaling removed for
// a dielectric of index eta > 0.
std::vector<double> sample_weights(const BSDF& bsdf, const Vec3& wo, int count, std::uint64_t seed, float eta = 0.0f) {
    PCG32 random(seed, 7);
    std::vector<double> weights;
    weights.reserve(count);
    for (int i = 0; i < count; ++i) {
        const Vec2 u(random.next_float(), random.next_float());
        const auto s = bsdf.sample(wo, u, random.next_float());
        if (!s) {
            weights.push_back(0.0);
            continue;
        }
        const float scale = eta > 0.0f ? s->eta * s->eta : 1.0f;
        weights.push_back(static_cast<double>(s->weight().x) * scale);
    }
    return weights;
}

// Every non-delta sample: wi a unit vector, f = eval(wo, wi), pdf = pdf(wo, wi) > 0, and a finite,
// non-negative weight f |cos| / pdf.
void check_samples_are_consistent(const BSDF& bsdf, const Vec3& wo, const char* name) {
    PCG32 random(3, 1);
    int non_delta = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec2 u(random.next_float(), random.next_float());
        const auto s = bsdf.sample(wo, u, random.next_float());
        if (!s) continue;
        INFO(name << ", wo (" << wo.x << ", " << wo.y << ", " << wo.z << "), sample " << i);
        REQUIRE(glm::length(s->wi) == Approx(1.0f).epsilon(1e-4));
        REQUIRE(is_valid_radiance(s->weight()));
        REQUIRE((s->flags & bsdf.flags()) == s->flags);
        if (has_flag(s->flags, BSDF_Specular)) continue;
        ++non_delta;
        const Spectrum f = bsdf.eval(wo, s->wi);
        const float pdf = bsdf.pdf(wo, s->wi);
        REQUIRE(pdf > 0.0f);
        REQUIRE(s->pdf == Approx(pdf).epsilon(2e-3));
        for (int c = 0; c < 3; ++c) REQUIRE(s->f[c] == Approx(f[c]).epsilon(2e-3).margin(1e-12));
        const Spectrum expected_weight = f * std::abs(s->wi.z) / pdf;
        for (int c = 0; c < 3; ++c) REQUIRE(s->weight()[c] == Approx(expected_weight[c]).epsilon(3e-3).margin(1e-9));
    }
    CHECK(non_delta > 0);
}

}  // namespace

TEST_CASE("a sample's f, pdf and weight agree with eval and pdf", "[unit][bsdf][ch02]") {
    const CosineLambertianBSDF lambertian(Spectrum(0.7f, 0.5f, 0.3f));
    const RoughConductorBSDF metal(isotropic(0.4f), Spectrum(0.2f, 0.9f, 1.1f), Spectrum(3.9f, 2.5f, 2.4f));
    const TrowbridgeReitz stretched(0.05f, 0.5f);
    const RoughConductorBSDF brushed(stretched, Spectrum(1.2f), Spectrum(6.0f));
    const RoughDielectricBSDF frosted(isotropic(0.3f), 1.5f);
    const TrowbridgeReitz coating = isotropic(0.3f);
    const PlasticBSDF rough_plastic(Spectrum(0.6f, 0.3f, 0.1f), 1.5f, &coating);
    const PlasticBSDF smooth_plastic(Spectrum(0.6f, 0.3f, 0.1f), 1.5f, nullptr);
    const MixBSDF mix(&lambertian, &metal, 0.4f);
    const SmoothDielectricBSDF glass(1.5f);
    const MixBSDF glass_and_paint(&glass, &lambertian, 0.5f);
    for (const Vec3& wo :
         {direction(0.9f, 0.2f), direction(0.3f, 2.0f), direction(0.01f, 4.0f), direction(-0.6f, 1.0f)}) {
        check_samples_are_consistent(lambertian, wo, "cosine Lambertian");
        check_samples_are_consistent(metal, wo, "rough conductor");
        check_samples_are_consistent(brushed, wo, "anisotropic rough conductor");
        check_samples_are_consistent(frosted, wo, "rough dielectric");
        check_samples_are_consistent(rough_plastic, wo, "rough plastic");
        check_samples_are_consistent(smooth_plastic, wo, "smooth plastic");
        check_samples_are_consistent(mix, wo, "mix");
        check_samples_are_consistent(glass_and_paint, wo, "mix with glass");
    }
}

TEST_CASE("delta lobes: mirror, smooth conductor and smooth dielectric", "[unit][bsdf][ch02]") {
    const Vec3 wo = direction(0.6f, 1.0f);
    const Vec3 mirror_direction(-wo.x, -wo.y, wo.z);

    const MirrorBSDF mirror(Spectrum(0.9f, 0.5f, 0.1f));
    const auto m = mirror.sample(wo, Vec2(0.3f), 0.7f);
    REQUIRE(m);
    CHECK(glm::length(m->wi - mirror_direction) < 1e-6f);
    CHECK(m->weight().x == Approx(0.9f));
    CHECK(m->weight().z == Approx(0.1f));
    CHECK(mirror.eval(wo, mirror_direction) == Spectrum(0.0f));
    CHECK(mirror.pdf(wo, mirror_direction) == 0.0f);

    const SpecularConductorBSDF gold(find_conductor_preset("gold")->eta, find_conductor_preset("gold")->k);
    const auto g = gold.sample(wo, Vec2(0.5f), 0.5f);
    REQUIRE(g);
    const Spectrum F = fresnel_conductor(wo.z, gold.eta(), gold.k());
    for (int c = 0; c < 3; ++c) CHECK(g->weight()[c] == Approx(F[c]));
    const auto g_below = gold.sample(-wo, Vec2(0.5f), 0.5f);  // both sides of the surface
    REQUIRE(g_below);
    CHECK(g_below->wi.z < 0.0f);

    // Glass: reflection when u_lobe < F, weight 1; refraction otherwise, weight 1 / eta'^2.
    const float eta = 1.5f;
    const SmoothDielectricBSDF glass(eta);
    const float R = fresnel_dielectric(wo.z, eta);
    const auto reflected = glass.sample(wo, Vec2(0.5f), R * 0.99f);
    const auto refracted = glass.sample(wo, Vec2(0.5f), R * 1.01f);
    REQUIRE(reflected);
    REQUIRE(refracted);
    CHECK(reflected->flags == (BSDF_Reflection | BSDF_Specular));
    CHECK(reflected->pdf == Approx(R));
    CHECK(reflected->weight().x == Approx(1.0f));
    CHECK(refracted->flags == (BSDF_Transmission | BSDF_Specular));
    CHECK(refracted->pdf == Approx(1.0f - R));
    CHECK(refracted->eta == eta);
    CHECK(refracted->wi.z < 0.0f);
    CHECK(refracted->weight().x == Approx(1.0f / (eta * eta)));
    // From inside, out: the radiance is multiplied by eta^2.
    const auto out = glass.sample(Vec3(0.0f, 0.0f, -1.0f), Vec2(0.5f), 0.999f);
    REQUIRE(out);
    CHECK(out->eta == Approx(1.0f / eta));
    CHECK(out->weight().x == Approx(eta * eta));
    // Total internal reflection: beyond the critical angle every sample reflects.
    const Vec3 steep_inside = direction(-0.3f, 2.0f);
    for (float u_lobe : {0.0f, 0.5f, 0.999999f}) {
        const auto t = glass.sample(steep_inside, Vec2(0.5f), u_lobe);
        REQUIRE(t);
        CHECK(t->flags == (BSDF_Reflection | BSDF_Specular));
        CHECK(t->weight().x == Approx(1.0f));
    }
    // Index-matched: straight through, all of it.
    const SmoothDielectricBSDF matched(1.0f);
    const auto through = matched.sample(wo, Vec2(0.5f), 0.0f);
    REQUIRE(through);
    CHECK(glm::length(through->wi + wo) < 1e-6f);
    CHECK(through->weight().x == Approx(1.0f));
    CHECK(matched.flags() == (BSDF_Transmission | BSDF_Specular));
}

TEST_CASE("a lossless smooth dielectric and a white mirror conserve energy exactly", "[unit][bsdf][ch02]") {
    // Every sample's weight is 1 once the radiance scaling 1 / eta'^2 is taken out: R + T = 1,
    // each lobe sampled with its own probability.
    for (float eta : {1.5f, 1.0f / 1.33f, 2.4f}) {
        const SmoothDielectricBSDF glass(eta);
        for (const Vec3& wo :
             {direction(0.9f, 0.2f), direction(0.2f, 2.0f), direction(-0.7f, 1.0f), direction(-0.1f, 3.0f)}) {
            const std::vector<double> weights = sample_weights(glass, wo, 200, 5, eta);
            for (double w : weights) CHECK(w == Approx(1.0).epsilon(1e-5));
            const float R = fresnel_dielectric(wo.z, eta);
            CHECK(R + (1.0f - R) == 1.0f);
        }
    }
    const MirrorBSDF white(Spectrum(1.0f));
    for (double w : sample_weights(white, direction(0.05f, 1.0f), 100, 5)) CHECK(w == Approx(1.0));
}

TEST_CASE("rough models become their smooth models when effectively smooth", "[unit][bsdf][ch02]") {
    CHECK(TrowbridgeReitz::roughness_to_alpha(0.5f) == Approx(0.25f));
    CHECK(isotropic(0.01f).effectively_smooth());  // alpha = 1e-4
    CHECK(isotropic(0.03f).effectively_smooth());  // alpha = 9e-4
    CHECK_FALSE(isotropic(0.05f).effectively_smooth());
    CHECK_FALSE(TrowbridgeReitz(1e-4f, 0.1f).effectively_smooth());

    const Vec3 wo = direction(0.7f, 0.4f);
    const Spectrum eta(0.2f, 0.9f, 1.1f);
    const Spectrum k(3.9f, 2.5f, 2.4f);
    const RoughConductorBSDF rough_metal(isotropic(0.01f), eta, k);
    const SpecularConductorBSDF smooth_metal(eta, k);
    CHECK(rough_metal.flags() == smooth_metal.flags());
    const auto a = rough_metal.sample(wo, Vec2(0.3f, 0.8f), 0.4f);
    const auto b = smooth_metal.sample(wo, Vec2(0.3f, 0.8f), 0.4f);
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a->wi == b->wi);
    CHECK(a->f == b->f);
    CHECK(rough_metal.eval(wo, b->wi) == Spectrum(0.0f));
    CHECK(rough_metal.pdf(wo, b->wi) == 0.0f);

    const RoughDielectricBSDF rough_glass(isotropic(0.01f), 1.5f);
    const SmoothDielectricBSDF smooth_glass(1.5f);
    CHECK(rough_glass.flags() == smooth_glass.flags());
    for (float u_lobe : {0.01f, 0.9f}) {
        const auto c = rough_glass.sample(wo, Vec2(0.3f, 0.8f), u_lobe);
        const auto d = smooth_glass.sample(wo, Vec2(0.3f, 0.8f), u_lobe);
        REQUIRE(c);
        REQUIRE(d);
        CHECK(c->wi == d->wi);
        CHECK(c->f == d->f);
        CHECK(c->flags == d->flags);
    }
    // A rough interface between equal indices scatters nothing: it is the index-matched smooth one.
    const RoughDielectricBSDF matched(isotropic(0.5f), 1.0f);
    CHECK(matched.flags() == (BSDF_Transmission | BSDF_Specular));

    const TrowbridgeReitz glassy_coating = isotropic(0.02f);
    const PlasticBSDF almost_smooth(Spectrum(0.5f), 1.5f, &glassy_coating);
    const PlasticBSDF smooth(Spectrum(0.5f), 1.5f, nullptr);
    CHECK(almost_smooth.flags() == smooth.flags());
    CHECK(has_flag(smooth.flags(), BSDF_Specular));
    const Vec3 wi = direction(0.3f, 2.0f);
    CHECK(almost_smooth.eval(wo, wi) == smooth.eval(wo, wi));
    CHECK(almost_smooth.pdf(wo, wi) == smooth.pdf(wo, wi));
}

TEST_CASE("reflection is reciprocal: f(wo, wi) = f(wi, wo)", "[unit][bsdf][ch02]") {
    const CosineLambertianBSDF lambertian(Spectrum(0.7f));
    const TrowbridgeReitz stretched(0.1f, 0.6f);
    const RoughConductorBSDF metal(stretched, Spectrum(0.2f, 0.9f, 1.1f), Spectrum(3.9f, 2.5f, 2.4f));
    const TrowbridgeReitz coating = isotropic(0.4f);
    const PlasticBSDF rough_plastic(Spectrum(0.6f, 0.3f, 0.1f), 1.5f, &coating);
    const PlasticBSDF smooth_plastic(Spectrum(0.6f, 0.3f, 0.1f), 1.5f, nullptr);
    const RoughDielectricBSDF frosted(isotropic(0.5f), 1.5f);
    const MixBSDF mix(&lambertian, &metal, 0.3f);
    const BSDF* reflectors[] = {&lambertian, &metal, &rough_plastic, &smooth_plastic, &frosted, &mix};

    PCG32 random(9, 2);
    for (int i = 0; i < 500; ++i) {
        Vec3 wo = direction(random.next_float(), 2.0f * Pi * random.next_float());
        Vec3 wi = direction(random.next_float(), 2.0f * Pi * random.next_float());
        if (i % 2 == 1) {  // and from below
            wo.z = -wo.z;
            wi.z = -wi.z;
        }
        for (const BSDF* bsdf : reflectors) {
            const Spectrum forward = bsdf->eval(wo, wi);
            const Spectrum backward = bsdf->eval(wi, wo);
            for (int c = 0; c < 3; ++c) REQUIRE(forward[c] == Approx(backward[c]).epsilon(1e-3).margin(1e-7));
        }
    }
}

TEST_CASE("rough transmission obeys the generalized reciprocity of refraction", "[unit][bsdf][ch02]") {
    // With the radiance scaling, f(wo, wi) eta'^2 = f(wi, wo), eta' = n(wi side) / n(wo side):
    // f / n^2 of the side light arrives from is symmetric (Veach 1997, section 5.2).
    const float eta = 1.5f;
    const RoughDielectricBSDF frosted(isotropic(0.5f), eta);
    PCG32 random(4, 2);
    int nonzero = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3 wo = direction(random.next_float(), 2.0f * Pi * random.next_float());
        const Vec3 wi = direction(-random.next_float(), 2.0f * Pi * random.next_float());
        const float forward = frosted.eval(wo, wi).x * eta * eta;
        const float backward = frosted.eval(wi, wo).x;
        REQUIRE(forward == Approx(backward).epsilon(1e-3).margin(1e-7));
        if (backward > 0.0f) ++nonzero;
    }
    CHECK(nonzero > 50);  // the test saw transmission, not just zeros
}

TEST_CASE("directional albedo never exceeds one (quadrature)", "[unit][bsdf][ch02]") {
    const Vec3 directions[] = {direction(1.0f, 0.0f), direction(0.7f, 0.5f), direction(0.3f, 1.0f),
                               direction(0.01f, 2.0f)};
    for (float roughness : {0.2f, 0.7f}) {
        const RoughConductorBSDF metal(isotropic(roughness), perfect_eta, perfect_k);
        const RoughDielectricBSDF glass(isotropic(roughness), 1.5f);
        for (const Vec3& wo : directions) {
            INFO("roughness " << roughness << ", cos theta_o " << wo.z);
            // Single scattering off a perfect reflector loses only the masked light: <= 1, and
            // close to 1 when smooth and not grazing.
            const double metal_albedo = albedo_by_quadrature(metal, wo);
            CHECK(metal_albedo <= 1.0 + 1e-4);
            if (roughness <= 0.2f && wo.z >= 0.3f) CHECK(metal_albedo > 0.97);
            // Glass (radiance scaling removed): R + T <= 1 from both sides.
            CHECK(albedo_by_quadrature(glass, wo, 1.5f) <= 1.0 + 1e-4);
            CHECK(albedo_by_quadrature(glass, -wo, 1.5f) <= 1.0 + 1e-4);
        }
    }
}

TEST_CASE("plastic's directional albedo is F + (1 - F) albedo, and at most one", "[unit][bsdf][ch02]") {
    // Smooth coating: the diffuse part integrates to (1 - F(cos o)) albedo exactly, and the delta
    // lobe reflects F(cos o).
    const float eta = 1.5f;
    for (float albedo : {0.0f, 0.5f, 1.0f}) {
        const PlasticBSDF plastic(Spectrum(albedo), eta, nullptr);
        for (float cos_theta : {1.0f, 0.5f, 0.1f}) {
            const Vec3 wo = direction(cos_theta, 0.7f);
            const float F = fresnel_dielectric(cos_theta, eta);
            INFO("albedo " << albedo << ", cos theta_o " << cos_theta);
            CHECK(albedo_by_quadrature(plastic, wo) + F == Approx(F + (1.0f - F) * albedo).margin(2e-5));
        }
    }
    // Rough coating: the base keeps the smooth coating's Fresnel factors (Mitsuba's roughplastic
    // replaces them by tabulated rough transmittances), so the coating's glossy lobe, whose Fresnel
    // factor is averaged over microfacets, can reflect slightly more than F(cos o): by up to 7e-4
    // for a white base (measured for alpha 0.0025 to 1, eta 1.2 to 2.5). It stays within 1e-3 of 1.
    for (float roughness : {0.2f, 0.3f, 0.5f, 1.0f}) {
        const TrowbridgeReitz coating = isotropic(roughness);
        const PlasticBSDF white(Spectrum(1.0f), 1.2f, &coating);
        for (float cos_theta : {1.0f, 0.8f, 0.6f, 0.3f, 0.05f}) {
            INFO("roughness " << roughness << ", cos theta_o " << cos_theta);
            CHECK(albedo_by_quadrature(white, direction(cos_theta, 0.3f)) <= 1.0 + 1e-3);
        }
    }
}

TEST_CASE("Monte Carlo: the mean sample weight is the directional albedo", "[unit][bsdf][ch02]") {
    // Six t-tests at unit_test_alpha, 2e5 samples each: the weights are bounded (at most about
    // 1.1 here), so their mean is close to normal. Together with the quadrature tests above: the
    // albedo a renderer sees through the weights never exceeds one.
    const float eta = 1.5f;
    const RoughConductorBSDF metal(isotropic(0.5f), perfect_eta, perfect_k);
    const TrowbridgeReitz stretched(0.1f, 0.7f);
    const RoughConductorBSDF brushed(stretched, perfect_eta, perfect_k);
    const RoughDielectricBSDF glass(isotropic(0.5f), eta);
    const TrowbridgeReitz coating = isotropic(0.4f);
    const PlasticBSDF plastic(Spectrum(0.8f), eta, &coating);
    const CosineLambertianBSDF diffuse(Spectrum(0.6f));
    const MixBSDF mix(&diffuse, &metal, 0.5f);
    struct Case {
        const char* name;
        const BSDF& bsdf;
        Vec3 wo;
        float eta;  // > 0: remove the radiance scaling of a dielectric
    };
    const Case cases[] = {
        {"rough conductor, grazing", metal, direction(0.05f, 1.0f), 0.0f},
        {"anisotropic rough conductor", brushed, direction(0.6f, 0.8f), 0.0f},
        {"rough dielectric from outside", glass, direction(0.6f, 0.8f), eta},
        {"rough dielectric from inside", glass, direction(-0.8f, 2.0f), eta},
        {"rough plastic", plastic, direction(0.4f, 0.3f), 0.0f},
        {"mix of diffuse and metal", mix, direction(0.7f, 0.1f), 0.0f},
    };
    std::uint64_t seed = 100;
    for (const Case& c : cases) {
        const double expected = albedo_by_quadrature(c.bsdf, c.wo, c.eta);
        const std::vector<double> weights = sample_weights(c.bsdf, c.wo, 200'000, ++seed, c.eta);
        const stats::TestResult test = stats::one_sample_t_test(weights, expected, stats::unit_test_alpha);
        INFO(c.name << ": albedo by quadrature " << expected << "; " << test.message);
        CHECK(test.passed);
        CHECK(expected <= 1.0 + 1e-3);
    }
}

TEST_CASE("the pdf of a BSDF that always samples integrates to one", "[unit][bsdf][ch02]") {
    const CosineLambertianBSDF lambertian(Spectrum(0.5f));
    const PlasticBSDF plastic(Spectrum(0.5f), 1.5f, nullptr);
    for (const Vec3& wo : {direction(0.8f, 0.1f), direction(-0.2f, 1.0f)}) {
        const auto pdf_of = [&](const BSDF& bsdf) {
            return stats::integrate_over_domain(stats::Domain::sphere(),
                                                [&](const Vec3& wi) { return double(bsdf.pdf(wo, wi)); });
        };
        CHECK(pdf_of(lambertian) == Approx(1.0).epsilon(1e-5));
        // Smooth plastic: the diffuse lobe's share; the delta lobe takes the rest.
        CHECK(pdf_of(plastic) == Approx(1.0 - plastic.specular_probability(wo)).epsilon(1e-5));
    }
}

TEST_CASE("MixBSDF blends, picks by weight, and scales delta samples by the choice", "[unit][bsdf][ch02]") {
    const CosineLambertianBSDF diffuse(Spectrum(0.8f));
    const SmoothDielectricBSDF glass(1.5f);
    const MixBSDF mix(&glass, &diffuse, 0.25f);
    CHECK(mix.flags() == (glass.flags() | diffuse.flags()));
    CHECK(MixBSDF(&glass, &diffuse, 0.0f).flags() == glass.flags());
    CHECK(MixBSDF(&glass, &diffuse, 1.0f).flags() == diffuse.flags());
    const Vec3 wo = direction(0.6f, 1.0f);
    const Vec3 wi = direction(0.4f, 3.0f);
    CHECK(mix.eval(wo, wi).x == Approx(0.25f * diffuse.eval(wo, wi).x));
    CHECK(mix.pdf(wo, wi) == Approx(0.25f * diffuse.pdf(wo, wi)));
    // u_lobe < 0.25 picks the diffuse BSDF, the rest the glass, whose own lobe choice sees
    // (u_lobe - 0.25) / 0.75: 0.26 maps to 0.0133 < F(0.6) = 0.0425, a reflection.
    const auto d = mix.sample(wo, Vec2(0.3f, 0.6f), 0.1f);
    REQUIRE(d);
    CHECK(d->flags == (BSDF_Reflection | BSDF_Diffuse));
    const auto r = mix.sample(wo, Vec2(0.3f, 0.6f), 0.26f);
    REQUIRE(r);
    CHECK(r->flags == (BSDF_Reflection | BSDF_Specular));
    const auto t = mix.sample(wo, Vec2(0.3f, 0.6f), 0.9f);
    REQUIRE(t);
    CHECK(t->flags == (BSDF_Transmission | BSDF_Specular));
    // A delta sample keeps its component's weight: its f and probability both carry the 0.75.
    const auto alone = glass.sample(wo, Vec2(0.3f, 0.6f), (0.9f - 0.25f) / 0.75f);
    REQUIRE(alone);
    CHECK(t->pdf == Approx(0.75f * alone->pdf));
    CHECK(t->weight().x == Approx(alone->weight().x));
}

TEST_CASE("no BSDF returns NaN, at grazing angles or on the horizon", "[unit][bsdf][ch02]") {
    const CosineLambertianBSDF lambertian(Spectrum(0.5f));
    const MirrorBSDF mirror(Spectrum(1.0f));
    const SpecularConductorBSDF smooth_metal(Spectrum(0.2f), Spectrum(3.0f));
    const RoughConductorBSDF rough_metal(isotropic(0.3f), Spectrum(0.2f), Spectrum(3.0f));
    const TrowbridgeReitz tiny(1e-3f, 1e-3f);  // just rough enough to stay a microfacet model
    const RoughConductorBSDF nearly_smooth_metal(tiny, Spectrum(0.2f), Spectrum(3.0f));
    const SmoothDielectricBSDF glass(1.5f);
    const RoughDielectricBSDF frosted(isotropic(0.3f), 1.5f);
    const RoughDielectricBSDF nearly_smooth_glass(tiny, 1.5f);
    const PlasticBSDF smooth_plastic(Spectrum(0.5f), 1.5f, nullptr);
    const TrowbridgeReitz coating = isotropic(0.3f);
    const PlasticBSDF rough_plastic(Spectrum(0.5f), 1.5f, &coating);
    const MixBSDF mix(&glass, &rough_metal, 0.5f);
    const BSDF* bsdfs[] = {&lambertian,          &mirror,        &smooth_metal, &rough_metal,
                           &nearly_smooth_metal, &glass,         &frosted,      &nearly_smooth_glass,
                           &smooth_plastic,      &rough_plastic, &mix};

    // On the horizon nothing can be sampled: no NaN, just no sample.
    for (const BSDF* bsdf : bsdfs) {
        CHECK_FALSE(bsdf->sample(Vec3(1.0f, 0.0f, 0.0f), Vec2(0.3f, 0.7f), 0.5f).has_value());
        CHECK(is_valid_radiance(bsdf->eval(Vec3(1.0f, 0.0f, 0.0f), direction(0.5f, 1.0f))));
        CHECK(std::isfinite(bsdf->pdf(Vec3(1.0f, 0.0f, 0.0f), direction(0.5f, 1.0f))));
    }
    // Grazing and random directions from both sides, extreme random numbers included.
    PCG32 random(21, 3);
    for (int i = 0; i < 20000; ++i) {
        const float cos_theta = i % 4 == 0 ? 1e-6f * random.next_float() : random.next_float();
        Vec3 wo = direction(cos_theta, 2.0f * Pi * random.next_float());
        if (i % 2 == 1) wo.z = -wo.z;
        if (wo.z == 0.0f) continue;
        const Vec2 u = i % 8 == 2
                           ? Vec2(0.0f, 0.0f)
                           : (i % 8 == 6 ? Vec2(0x1.fffffep-1f) : Vec2(random.next_float(), random.next_float()));
        const float u_lobe = random.next_float();
        for (const BSDF* bsdf : bsdfs) {
            const auto s = bsdf->sample(wo, u, u_lobe);
            if (!s) continue;
            INFO("sample " << i << ", wo (" << wo.x << ", " << wo.y << ", " << wo.z << ")");
            REQUIRE(is_valid_radiance(s->f));
            REQUIRE(std::isfinite(s->pdf));
            REQUIRE(s->pdf > 0.0f);
            REQUIRE(is_valid_radiance(s->weight()));
            REQUIRE(std::abs(glm::length(s->wi) - 1.0f) < 1e-3f);
            REQUIRE(is_valid_radiance(bsdf->eval(wo, s->wi)));
            REQUIRE(std::isfinite(bsdf->pdf(wo, s->wi)));
        }
    }
}
