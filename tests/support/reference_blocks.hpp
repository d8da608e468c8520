// Grading an assignment by what it renders: the student's code renders the assignment's views in
// independent batches, and each block of pixels is compared with the solution's reference render
// of the same view (tests/data/references/chNN-name.json, written by
// tests/grading/make_references.py --blocks from other seeds). A block of pixels averages away
// most of the noise, so a few hundred samples per pixel show a bias of a few percent, while the
// comparison stays a hypothesis test with a known false-failure rate.
#pragma once

#include <cstdint>
#include <string>

namespace freezeray::testing {

struct ReferenceComparison {
    bool passed = false;
    std::string message;   // one line: the worst block, or why nothing could be compared
    std::string evidence;  // on failure, "evidence: FOLDER" (evidence.hpp), else ""
};

// Renders each view of `assignment`'s reference in `batches` renders of `spp_per_batch` samples
// (seeds first_seed, first_seed + 1, ...; the reference's seeds must differ) and tests, for every
// block and channel, and for the whole image per channel (where a small bias everywhere shows), "the
// mean of the student's batches equals the reference's" by Welch's t-test (the reference's standard
// error comes from its own batches). The false-failure rate of the
// whole comparison is `alpha`, shared over the blocks, channels and views by Šidák's correction.
// Samples that are NaN, Inf or negative fail it too. On failure the evidence folder holds, for
// the first view that differs, the student's render (mean of the batches, mine.pfm), its block
// means beside the reference's (mine-blocks.pfm, reference-blocks.pfm: one pixel per block) and
// the t statistic of each block and channel (t.pfm).
ReferenceComparison compare_with_reference(const std::string& assignment, int batches, std::uint64_t spp_per_batch,
                                           std::uint64_t first_seed, double alpha);

}  // namespace freezeray::testing
