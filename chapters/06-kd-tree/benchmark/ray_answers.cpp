// Counting disagreements between two tracers' answers.
#include "ray_answers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace freezeray::benchmark {

Disagreements compare_answers(const RayAnswers& answers, const RayAnswers& reference) {
    if (answers.closest.size() != reference.closest.size() || answers.occluded.size() != reference.occluded.size())
        throw std::logic_error("compare_answers: the two answers are for batches of different sizes");
    Disagreements result;
    for (std::size_t i = 0; i < answers.closest.size(); ++i) {
        const ClosestHit& a = answers.closest[i];
        const ClosestHit& b = reference.closest[i];
        if (a.triangle == b.triangle) continue;
        if (a.is_miss() || b.is_miss()) {
            ++result.differ;
            continue;
        }
        const float scale = std::max(std::abs(a.t), std::abs(b.t));
        if (std::abs(a.t - b.t) <= TieRelativeTolerance * scale)
            ++result.ties;
        else
            ++result.differ;
    }
    for (std::size_t i = 0; i < answers.occluded.size(); ++i)
        if (answers.occluded[i] != reference.occluded[i]) ++result.differ;
    return result;
}

}  // namespace freezeray::benchmark
