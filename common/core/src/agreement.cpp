// Whether renders of one scene agree within their own noise.
#include "freezeray/agreement.hpp"

#include "freezeray/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace freezeray {

// BOOK(agreement)
Agreement agreement(const RenderResult& a, const RenderResult& b) {
    Agreement result;
    if (a.image.width() != b.image.width() || a.image.height() != b.image.height() ||
        a.variance.width() != a.image.width() || b.variance.width() != b.image.width() ||
        a.variance.height() != a.image.height() || b.variance.height() != b.image.height())
        return result;
    double squared_differences = 0.0, variances = 0.0, spread = 0.0;
    for (std::size_t i = 0; i < a.image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double difference = double(a.image[i][c]) - double(b.image[i][c]);
            const double variance = double(a.variance[i][c]) + double(b.variance[i][c]);
            if (variance > 0.0) {
                const double mean = 0.5 * (double(a.image[i][c]) + double(b.image[i][c]));
                const double w = 1.0 / (mean * mean + RelativeMseEpsilon);
                squared_differences += w * difference * difference;
                variances += w * variance;
                // Var[(a - b)^2] = 2 (Var a + Var b)^2 for a normal difference, and about as much
                // again for the variances' own estimates.
                spread += 4.0 * w * w * variance * variance;
                ++result.terms;
            } else if (difference != 0.0) {
                ++result.one_sided;
            }
        }
    if (variances > 0.0) {
        result.statistic = squared_differences / variances;
        result.standard_error = std::sqrt(spread) / variances;
    }
    return result;
}

bool Agreement::disagree() const {
    if (one_sided > 0) return true;
    return terms > 0 && statistic > 1.0 + 6.0 * standard_error;
}
// END BOOK

std::vector<RunAgreement> pairwise_agreements(const std::vector<const RenderResult*>& results) {
    std::vector<RunAgreement> result;
    for (std::size_t i = 0; i < results.size(); ++i)
        for (std::size_t j = i + 1; j < results.size(); ++j) {
            const Agreement agree = agreement(*results[i], *results[j]);
            if (agree.terms > 0 || agree.one_sided > 0) result.push_back({i, j, agree});  // else no variances
        }
    return result;
}

std::optional<std::size_t> odd_one_out(const std::vector<RunAgreement>& agreements, std::size_t runs) {
    if (runs < 3) return std::nullopt;
    // excess[i][j]: D - 1 for the pair, when it disagrees; 0 when it agrees; NaN when unknown.
    const double unknown = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::vector<double>> excess(runs, std::vector<double>(runs, unknown));
    for (const RunAgreement& pair : agreements)
        if (pair.first < runs && pair.second < runs)
            excess[pair.first][pair.second] = excess[pair.second][pair.first] =
                pair.agreement.disagree() ? pair.agreement.statistic - 1.0 : 0.0;
    for (std::size_t i = 0; i < runs; ++i) {
        double smallest_own = std::numeric_limits<double>::infinity(), largest_others = 0.0;
        bool known = true;
        for (std::size_t j = 0; j < runs; ++j) {
            if (j == i) continue;
            known = known && !std::isnan(excess[i][j]);
            smallest_own = std::min(smallest_own, excess[i][j]);
            for (std::size_t k = j + 1; k < runs; ++k)
                if (k != i) {
                    known = known && !std::isnan(excess[j][k]);
                    largest_others = std::max(largest_others, excess[j][k]);
                }
        }
        if (known && smallest_own > 0.0 && smallest_own >= OddOneOutRatio * largest_others) return i;
    }
    return std::nullopt;
}

}  // namespace freezeray
