// What a tracer answered for one batch, and counting where two tracers' answers differ.
#pragma once

#include "hit_file.hpp"
#include "ray_batch.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace freezeray::benchmark {

// One answer per ray of a batch: the closest hits (primary, diffuse) or the occluded flags
// (shadow); the other vector is empty.
struct RayAnswers {
    std::vector<ClosestHit> closest;
    std::vector<std::uint8_t> occluded;  // 1: something is in the way
};

struct Disagreements {
    std::size_t differ = 0;  // rays whose answers differ
    std::size_t ties = 0;    // of the rest: different triangles at the same distance
};

// The relative difference in t below which two different triangles count as a tie: a ray
// through an edge or vertex shared by several triangles may rightly report any of them.
inline constexpr float TieRelativeTolerance = 1e-6f;

// Compares two tracers' answers for the same batch. A closest-hit ray differs when one answer
// is a hit and the other a miss, or both hit different triangles at distances that differ by
// more than TieRelativeTolerance (relative to the larger); different triangles within that
// tolerance are counted as ties instead. A shadow ray differs when the occluded answers differ
// (a yes or no has no ties). Answers for different numbers of rays are a programming error.
Disagreements compare_answers(const RayAnswers& answers, const RayAnswers& reference);

}  // namespace freezeray::benchmark
