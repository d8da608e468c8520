// The Fresnel equations and the laws of reflection and refraction (chapter 02, fresnel.hpp),
// against closed forms and textbook values. Deterministic.
#include "freezeray/ch02/fresnel.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace freezeray;
using namespace freezeray::ch02;

namespace {

// The unpolarised reflectance from the angles, in double: Fresnel's sine and tangent laws
// (Born and Wolf, "Principles of Optics", section 1.5.2), a form independent of the code's.
double fresnel_from_angles(double theta_i, double eta) {
    const double theta_t = std::asin(std::sin(theta_i) / eta);
    const double rs = std::sin(theta_i - theta_t) / std::sin(theta_i + theta_t);
    const double rp = std::tan(theta_i - theta_t) / std::tan(theta_i + theta_t);
    return 0.5 * (rs * rs + rp * rp);
}

// The diffuse reflectance 2 int_0^1 F(c, eta) c dc by composite Simpson quadrature in double.
// Below the critical cosine (eta < 1) F is 1; that kink is placed on a node.
double diffuse_reflectance_by_quadrature(float eta) {
    const double critical = eta < 1.0f ? std::sqrt(1.0 - double(eta) * eta) : 0.0;
    auto integrate = [&](double a, double b) {
        constexpr int Intervals = 20000;
        const double h = (b - a) / Intervals;
        double sum = 0.0;
        for (int i = 0; i <= Intervals; ++i) {
            const double c = a + i * h;
            const double weight = (i == 0 || i == Intervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
            sum += weight * fresnel_dielectric(static_cast<float>(c), eta) * 2.0 * c;
        }
        return sum * h / 3.0;
    };
    return (critical > 0.0 ? integrate(0.0, critical) : 0.0) + integrate(critical, 1.0);
}

double normal_incidence_reflectance(double n, double k) {
    return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
}

}  // namespace

TEST_CASE("dielectric Fresnel: 4 % at normal incidence on glass, from both sides", "[unit][fresnel]") {
    // ((eta - 1) / (eta + 1))^2 = (0.5 / 2.5)^2 = 0.04 exactly.
    CHECK(fresnel_dielectric(1.0f, 1.5f) == Approx(0.04).margin(1e-6));
    CHECK(fresnel_dielectric(-1.0f, 1.5f) == Approx(0.04).margin(1e-6));
    CHECK(fresnel_dielectric(1.0f, 1.0f / 1.5f) == Approx(0.04).margin(1e-6));
    // An index-matched interface reflects nothing at any angle.
    for (float c : {1.0f, 0.5f, 0.01f}) CHECK(fresnel_dielectric(c, 1.0f) == Approx(0.0).margin(1e-7));
}

TEST_CASE("dielectric Fresnel matches the sine and tangent laws at every angle", "[unit][fresnel]") {
    for (double eta : {1.33, 1.5, 2.4}) {
        for (double degrees : {10.0, 30.0, 45.0, 60.0, 80.0, 89.0}) {
            const double theta = degrees * 3.14159265358979323846 / 180.0;
            INFO("eta " << eta << ", theta " << degrees << " degrees");
            const float cos_theta = static_cast<float>(std::cos(theta));
            CHECK(fresnel_dielectric(cos_theta, static_cast<float>(eta)) ==
                  Approx(fresnel_from_angles(theta, eta)).epsilon(1e-5));
            // Unpolarised light reflects the mean of the two polarisations.
            CHECK(fresnel_dielectric(cos_theta, float(eta)) ==
                  Approx(0.5 * (fresnel_dielectric_s_polarised(cos_theta, float(eta)) +
                                fresnel_dielectric_p_polarised(cos_theta, float(eta))))
                      .epsilon(1e-6));
        }
    }
}

TEST_CASE("dielectric Fresnel is the same for both directions through the interface", "[unit][fresnel]") {
    // Reciprocity (Stokes relations): light crossing from outside at theta_i reflects as much as
    // light coming back from inside along the refracted direction theta_t.
    const float eta = 1.5f;
    for (float cos_i : {0.9f, 0.6f, 0.3f, 0.05f}) {
        const float sin_t = std::sqrt(1.0f - cos_i * cos_i) / eta;
        const float cos_t = std::sqrt(1.0f - sin_t * sin_t);
        CHECK(fresnel_dielectric(cos_i, eta) == Approx(fresnel_dielectric(-cos_t, eta)).epsilon(1e-4));
    }
}

TEST_CASE("p-polarised reflectance vanishes at Brewster's angle", "[unit][fresnel]") {
    for (float eta : {1.33f, 1.5f, 2.0f}) {
        // From outside at atan(eta); from inside at atan(1 / eta).
        const float outside = std::cos(std::atan(eta));
        const float inside = std::cos(std::atan(1.0f / eta));
        CHECK(fresnel_dielectric_p_polarised(outside, eta) == Approx(0.0).margin(1e-6));
        CHECK(fresnel_dielectric_p_polarised(-inside, eta) == Approx(0.0).margin(1e-6));
        // The s-polarised part does not vanish there, so the reflection is polarised.
        CHECK(fresnel_dielectric_s_polarised(outside, eta) > 0.01f);
        // A little away from it, r_p is clearly positive.
        CHECK(fresnel_dielectric_p_polarised(std::cos(std::atan(eta) + 0.1f), eta) > 1e-4f);
    }
}

TEST_CASE("total internal reflection beyond the critical angle from inside", "[unit][fresnel]") {
    const float eta = 1.5f;
    const float critical_sin = 1.0f / eta;  // theta_c = 41.8 degrees
    const float critical_cos = std::sqrt(1.0f - critical_sin * critical_sin);
    for (float cos_theta : {0.01f, 0.3f, 0.7f, critical_cos - 1e-3f}) {
        CHECK(fresnel_dielectric(-cos_theta, eta) == 1.0f);
        CHECK(fresnel_dielectric(cos_theta, 1.0f / eta) == 1.0f);  // the same interface, eta given inverted
        CHECK(fresnel_dielectric_s_polarised(-cos_theta, eta) == 1.0f);
        CHECK(fresnel_dielectric_p_polarised(-cos_theta, eta) == 1.0f);
        CHECK_FALSE(
            refract(Vec3(std::sqrt(1 - cos_theta * cos_theta), 0.0f, -cos_theta), Vec3(0, 0, 1), eta).has_value());
    }
    // Inside the critical angle light gets out, and grazing light from outside is all reflected.
    CHECK(fresnel_dielectric(-(critical_cos + 1e-2f), eta) < 1.0f);
    CHECK(fresnel_dielectric(1e-6f, eta) == Approx(1.0).margin(1e-4));
}

TEST_CASE("refraction obeys Snell's law from both sides; reflection mirrors", "[unit][fresnel]") {
    const Vec3 n(0.0f, 0.0f, 1.0f);
    for (float eta : {1.5f, 1.0f / 1.33f}) {
        for (float cos_i : {1.0f, 0.8f, 0.4f, -0.95f, -0.5f}) {
            const Vec3 w(std::sqrt(1.0f - cos_i * cos_i), 0.0f, cos_i);
            const auto t = refract(w, n, eta);
            const float eta_i_over_t = cos_i > 0.0f ? 1.0f / eta : eta;  // n_i / n_t
            const float sin_t = std::sqrt(1.0f - cos_i * cos_i) * eta_i_over_t;
            INFO("eta " << eta << ", cos_i " << cos_i);
            if (sin_t >= 1.0f) {
                CHECK_FALSE(t.has_value());
                continue;
            }
            REQUIRE(t.has_value());
            CHECK(glm::length(*t) == Approx(1.0f).epsilon(1e-5));
            CHECK(std::sqrt(t->x * t->x + t->y * t->y) == Approx(sin_t).margin(1e-5));
            CHECK(t->z * cos_i < 0.0f);  // crossed to the other side
            CHECK(t->x * w.x <= 0.0f);   // and continues away from the plane of w
        }
    }
    const Vec3 w = glm::normalize(Vec3(0.3f, -0.4f, 0.8f));
    const Vec3 r = reflect(w, n);
    CHECK(r.x == Approx(-w.x));
    CHECK(r.y == Approx(-w.y));
    CHECK(r.z == Approx(w.z));
}

TEST_CASE("conductor Fresnel at normal incidence is ((n-1)^2 + k^2) / ((n+1)^2 + k^2)", "[unit][fresnel]") {
    const Spectrum eta(0.2f, 1.0f, 2.5f);
    const Spectrum k(3.5f, 0.5f, 0.0f);
    const Spectrum R = fresnel_conductor(1.0f, eta, k);
    for (int c = 0; c < 3; ++c) CHECK(R[c] == Approx(normal_incidence_reflectance(eta[c], k[c])).epsilon(1e-5));
    // Same on the other side, and k = 0 is a dielectric.
    const Spectrum below = fresnel_conductor(-0.6f, eta, k);
    const Spectrum above = fresnel_conductor(0.6f, eta, k);
    for (int c = 0; c < 3; ++c) CHECK(below[c] == above[c]);
    for (float cos_theta : {1.0f, 0.7f, 0.2f})
        CHECK(fresnel_conductor(cos_theta, Spectrum(1.5f), Spectrum(0.0f)).x ==
              Approx(fresnel_dielectric(cos_theta, 1.5f)).epsilon(1e-5));
    // Every metal becomes a perfect mirror at grazing incidence.
    const Spectrum grazing = fresnel_conductor(0.0f, eta, k);
    for (int c = 0; c < 3; ++c) CHECK(grazing[c] == Approx(1.0f).margin(1e-5));
}

TEST_CASE("conductor presets reflect like the published measurements of their metal", "[unit][fresnel]") {
    REQUIRE(conductor_preset_names() == std::vector<std::string>{"gold", "silver", "copper", "aluminium"});
    REQUIRE(find_conductor_preset("aluminum") == find_conductor_preset("aluminium"));
    REQUIRE(find_conductor_preset("unobtainium") == nullptr);

    // Normal-incidence reflectance at 650, 550 and 450 nm from independent measurements:
    // Johnson and Christy, "Optical Constants of the Noble Metals", Phys. Rev. B 6, 4370, 1972
    // (gold, silver, copper), and Rakic, "Algorithm for the determination of intrinsic optical
    // constants of metal films: application to aluminum", Appl. Opt. 34, 4755, 1995; n and k from
    // refractiveindex.info, interpolated linearly in wavelength, R = ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
    // The presets come from McPeak et al. 2015 (fresnel.cpp). Films differ: the two sources agree
    // to 0.01 except on the absorption edges of gold (550 nm: 0.79 vs 0.85) and copper (0.62 vs
    // 0.67), so the tolerance is 0.06 in reflectance.
    struct Published {
        const char* name;
        Spectrum reflectance;
    };
    const Published published[] = {
        {"gold", Spectrum(0.9565f, 0.7916f, 0.4082f)},
        {"silver", Spectrum(0.9898f, 0.9831f, 0.9802f)},
        {"copper", Spectrum(0.9352f, 0.6235f, 0.5383f)},
        {"aluminium", Spectrum(0.9056f, 0.9154f, 0.9219f)},
    };
    for (const Published& metal : published) {
        const ConductorPreset* preset = find_conductor_preset(metal.name);
        REQUIRE(preset != nullptr);
        const Spectrum R = fresnel_conductor(1.0f, preset->eta, preset->k);
        for (int c = 0; c < 3; ++c) {
            INFO(metal.name << ", channel " << c);
            CHECK(R[c] == Approx(metal.reflectance[c]).margin(0.06));
        }
    }
    // The colours: gold and copper reflect red best, silver and aluminium are nearly neutral.
    for (const char* name : {"gold", "copper"}) {
        const ConductorPreset* p = find_conductor_preset(name);
        const Spectrum R = fresnel_conductor(1.0f, p->eta, p->k);
        CHECK(R.r > R.g);
        CHECK(R.g > R.b);
    }
}

TEST_CASE("diffuse Fresnel reflectance matches quadrature and reciprocity", "[unit][fresnel]") {
    for (float eta : {1.001f, 1.05f, 1.33f, 1.5f, 2.5f, 1.0f / 1.5f, 0.9f}) {
        INFO("eta " << eta);
        CHECK(fresnel_diffuse_reflectance(eta) == Approx(diffuse_reflectance_by_quadrature(eta)).margin(2e-6));
        // What is not reflected is transmitted; radiance scales by eta^2 across the interface:
        // 1 - r(eta) = eta^2 (1 - r(1 / eta)).
        CHECK(1.0f - fresnel_diffuse_reflectance(eta) ==
              Approx(eta * eta * (1.0f - fresnel_diffuse_reflectance(1.0f / eta))).epsilon(1e-5));
    }
    CHECK(fresnel_diffuse_reflectance(1.0f) == 0.0f);
}
