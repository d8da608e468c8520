// The chi-square test of a light's sample_li against its own pdf_li on the sphere of directions,
// as seen from one reference point (chapter 03's lights; used by the chi2 and exercise tests).
#pragma once

#include "chi_square.hpp"

#include "freezeray/light.hpp"

#include <cstdint>

namespace freezeray::testing {

struct LightChiSquare {
    stats::ChiSquareResult result;
    std::uint64_t samples_moved_across_edges = 0;
};

// Runs stats::chi_square_test of light.sample_li(reference, .) against light.pdf_li(reference, .),
// with the directions turned by `view` before they are binned (and turned back for the pdf): the
// harness's cells are slivers near its poles (+-z), where a small light's outline can cut cells
// into pieces its quadrature misses; turned to the equator, the cells are nearly square.
//
// A sampled direction is computed from a point (on a triangle, in an image), and pdf_li finds
// that point again from the direction: rounding can put a point sampled on an edge just outside,
// off the triangle or in a black pixel, where pdf_li is zero (about 1 sample in 1e5, measured).
// The harness would count any such sample as a deterministic failure. Such a sample is moved
// across the edge instead, to the first direction within 1e-5 (radians, about) where the pdf is
// positive: far too small a move for the histogram to see, and counted, so that a test can bound
// how often it happens. A sample with no such neighbour is returned as it is, and fails.
inline LightChiSquare light_chi_square_test(const Light& light, const Vec3& reference,
                                            const stats::ChiSquareOptions& options, const Mat3& view = Mat3(1.0f)) {
    const bool turned = view != Mat3(1.0f);
    const Mat3 back = glm::transpose(view);
    const auto pdf = [&](const Vec3& w) { return static_cast<double>(light.pdf_li(reference, turned ? back * w : w)); };
    LightChiSquare test;
    test.result = stats::chi_square_test(
        stats::Domain::sphere(),
        [&](PCG32& r) -> std::optional<Vec3> {
            const Vec2 u(r.next_float(), r.next_float());
            const std::optional<LightSample> s = light.sample_li(reference, u);
            if (!s) return std::nullopt;
            const Vec3 w = turned ? view * s->wi : s->wi;
            if (pdf(w) > 0.0) return w;
            ++test.samples_moved_across_edges;
            for (int axis = 0; axis < 3; ++axis)
                for (const float sign : {-1.0f, 1.0f}) {
                    Vec3 nudged = w;
                    nudged[axis] += sign * 1e-5f;
                    nudged = glm::normalize(nudged);
                    if (pdf(nudged) > 0.0) return nudged;
                }
            return w;
        },
        pdf, options);
    return test;
}

}  // namespace freezeray::testing
