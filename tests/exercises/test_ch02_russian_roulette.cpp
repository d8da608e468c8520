// Grading test of chapter 02's Russian roulette exercise: exact decisions and weights, the
// estimator's expectation kept, and the classic mistakes named.
#include "freezeray/ch02/path_tracer.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace freezeray;

namespace {

// What russian_roulette did to one weight for one u: the q it returned and the weight after.
struct Outcome {
    float q;
    Spectrum weight;
};

Outcome play(Spectrum weight, float u) {
    const float q = ch02::russian_roulette(weight, u);
    return {q, weight};
}

bool same(const Spectrum& a, const Spectrum& b, float tolerance = 1e-6f) {
    for (int c = 0; c < 3; ++c)
        if (!(std::abs(a[c] - b[c]) <= tolerance * std::max(1.0f, std::abs(b[c])))) return false;
    return true;
}

// The classic mistakes, recognised from what a survivor and a stopped path look like.
std::string likely_mistake() {
    const Spectrum w(0.5f, 0.2f, 0.1f);  // q = 0.5
    const Outcome low = play(w, 0.1f);   // must survive, divided by 0.5
    const Outcome high = play(w, 0.9f);  // must stop
    if (low.q == 0.0f && high.q != 0.0f)
        return "likely mistake: the decision is inverted (a path goes on when u < q, and stops otherwise)";
    if (low.q != 0.0f && same(low.weight, w))
        return "likely mistake: Russian roulette without reweighting (a survivor's weight must be divided by q, "
               "or the estimate loses the light of the paths stopped and comes out dark)";
    if (low.q != 0.0f && same(low.weight, w * 0.5f))
        return "likely mistake: the survivor's weight is multiplied by q instead of divided";
    if (low.q != 0.0f && same(low.weight, w * 4.0f))
        return "likely mistake: the survivor's weight is divided by q twice";
    const Outcome bright = play(Spectrum(2.0f, 0.1f, 0.1f), 0.97f);
    if (bright.q != 0.0f)
        return "likely mistake: q is not capped at 0.95 (a path whose weight exceeds 1 would never stop)";
    const Outcome dim = play(Spectrum(0.1f, 0.3f, 0.05f), 0.2f);
    if (dim.q == 0.0f)
        return "likely mistake: q is not the largest component of the weight (the mean or the first one?)";
    return "";
}

}  // namespace

TEST_CASE("ch02/russian-roulette", "[exercise]") {
    const Spectrum w(0.5f, 0.2f, 0.1f);
    const Outcome first = play(w, 0.3f);  // its own code first
    INFO(likely_mistake());

    // Continue with probability q = the largest component, at most 0.95; survivors divided by q.
    CHECK(first.q == Approx(0.5f));
    CHECK(same(first.weight, Spectrum(1.0f, 0.4f, 0.2f)));
    const Outcome stopped = play(w, 0.5f);  // u = q: stops (it goes on only when u < q)
    CHECK(stopped.q == 0.0f);
    CHECK(same(stopped.weight, w));  // a stopped path's weight is left as it was
    CHECK(play(Spectrum(0.1f, 0.3f, 0.05f), 0.29f).q == Approx(0.3f));
    CHECK(play(Spectrum(0.1f, 0.3f, 0.05f), 0.31f).q == 0.0f);
    const Outcome bright = play(Spectrum(2.0f, 0.1f, 0.1f), 0.94f);
    CHECK(bright.q == Approx(0.95f));
    CHECK(same(bright.weight, Spectrum(2.0f, 0.1f, 0.1f) / 0.95f));
    CHECK(play(Spectrum(2.0f, 0.1f, 0.1f), 0.95f).q == 0.0f);
    CHECK(play(Spectrum(0.0f), 0.0f).q == 0.0f);  // a path that carries nothing stops

    // Unbiased: over u uniform in [0, 1) (midpoints of 1000 strata) the expected weight after the
    // roulette, 0 for a stopped path, is the weight before; only the stratum that straddles q is
    // off, by at most (w / q) / 1000, a relative error of 1 / (1000 q).
    for (const Spectrum& before : {Spectrum(0.5f, 0.2f, 0.1f), Spectrum(0.03f, 0.01f, 0.02f), Spectrum(3.0f)}) {
        constexpr int Strata = 1000;
        Spectrum mean(0.0f);
        for (int i = 0; i < Strata; ++i) {
            const Outcome after = play(before, (i + 0.5f) / Strata);
            if (after.q != 0.0f) mean += after.weight * (1.0f / Strata);
        }
        const double q = std::min(0.95f, std::max({before[0], before[1], before[2]}));
        for (int c = 0; c < 3; ++c) CHECK(mean[c] == Approx(before[c]).epsilon(1.0 / (Strata * q) + 1e-5));
    }
}
