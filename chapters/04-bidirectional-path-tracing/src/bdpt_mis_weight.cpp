// The MIS weight of a bidirectional strategy (book chapter 04; Veach 1997, section 10.3;
// pbrt-v3, section 16.3.4).
#include "freezeray/ch04/bdpt_mis_weight.hpp"

namespace freezeray::ch04 {

// BOOK(strategy-ratio)
double next_strategy_ratio(double ratio, float pdf_reverse, float pdf_forward) {
    // EXERCISE(ch04/strategy-ratio): one step of the ratio recurrence of book chapter 04, "The ratio recurrence", with the convention it states for densities that are 0 (delta vertices)
    const double reverse = pdf_reverse != 0.0f ? static_cast<double>(pdf_reverse) : 1.0;
    const double forward = pdf_forward != 0.0f ? static_cast<double>(pdf_forward) : 1.0;
    return ratio * reverse / forward;
    // END EXERCISE
}
// END BOOK

// BOOK(bdpt-mis-weight)
float bdpt_mis_weight(const Scene& scene, const ch03::FixedLightSampler& lights, ch03::MisHeuristic heuristic,
                      const PathVertex* light, int s, const PathVertex* camera, int t, const PathVertex* sampled) {
    // The vertices on either side of the connecting edge, and their predecessors.
    const PathVertex* pt = (t == 1 && sampled != nullptr) ? sampled : &camera[t - 1];
    const PathVertex* qs = s > 0 ? ((s == 1 && t != 1 && sampled != nullptr) ? sampled : &light[s - 1]) : nullptr;
    const PathVertex* pt_minus = t > 1 ? &camera[t - 2] : nullptr;
    const PathVertex* qs_minus = s > 1 ? &light[s - 2] : nullptr;

    // The reverse densities at the connection depend on the other subpath: the density with
    // which the other side would have made pt, pt_minus, qs and qs_minus (Veach 1997,
    // section 10.3.4). With s = 0, pt is on a light and is reached as a light subpath's origin.
    const float pt_reverse = s > 0 ? vertex_pdf(scene, *qs, qs_minus, *pt) : light_origin_pdf(lights, *pt, *pt_minus);
    const float pt_minus_reverse =
        pt_minus == nullptr ? 0.0f : (s > 0 ? vertex_pdf(scene, *pt, qs, *pt_minus) : light_pdf(*pt, *pt_minus));
    const float qs_reverse = qs != nullptr ? vertex_pdf(scene, *pt, pt_minus, *qs) : 0.0f;
    const float qs_minus_reverse = qs_minus != nullptr ? vertex_pdf(scene, *qs, pt, *qs_minus) : 0.0f;

    auto camera_vertex = [&](int i) -> const PathVertex& { return i == t - 1 ? *pt : camera[i]; };
    auto camera_reverse = [&](int i) {
        return i == t - 1 ? pt_reverse : i == t - 2 ? pt_minus_reverse : camera[i].pdf_rev;
    };
    // The two connected vertices are connectible by construction: not delta for this path.
    auto camera_delta = [&](int i) { return i == t - 1 ? false : camera[i].delta; };
    auto light_vertex = [&](int i) -> const PathVertex& { return i == s - 1 ? *qs : light[i]; };
    auto light_reverse = [&](int i) {
        return i == s - 1 ? qs_reverse : i == s - 2 ? qs_minus_reverse : light[i].pdf_rev;
    };
    auto light_delta = [&](int i) { return i == s - 1 ? false : light[i].delta; };
    auto term = [&](double ratio) { return heuristic == ch03::MisHeuristic::Power ? ratio * ratio : ratio; };

    // Strategies with fewer camera vertices, (s + t - i, i) for i = t - 1 ... 1: each moves
    // the connection one vertex towards the camera.
    double sum = 0.0;
    double ratio = 1.0;
    for (int i = t - 1; i >= 1; --i) {
        ratio = next_strategy_ratio(ratio, camera_reverse(i), camera_vertex(i).pdf_fwd);
        if (camera_delta(i) || camera_delta(i - 1)) continue;  // a connection at a delta vertex: impossible
        const bool light_seen_directly = i == 1 && s + t == 2;  // (1, 1): implemented for area lights only
        if (light_seen_directly && (pt->light == nullptr || pt->light->type() != LightType::Area)) continue;
        sum += term(ratio);
    }
    // Strategies with fewer light vertices, (i, s + t - i) for i = s - 1 ... 0.
    ratio = 1.0;
    for (int i = s - 1; i >= 0; --i) {
        ratio = next_strategy_ratio(ratio, light_reverse(i), light_vertex(i).pdf_fwd);
        const bool delta_before = i > 0 ? light_delta(i - 1) : light_vertex(0).is_delta_light();
        if (light_delta(i) || delta_before) continue;  // i = 0: no ray can hit a delta light
        sum += term(ratio);
    }
    return static_cast<float>(1.0 / (1.0 + sum));
}
// END BOOK

}  // namespace freezeray::ch04
