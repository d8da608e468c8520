// The state of a Markov chain in primary sample space (Kelemen, Szirmay-Kalos, Antal and
// Csonka 2002): the vector of uniform numbers a bidirectional sample reads, extended lazily as
// the sample asks for more, mutated by small and large steps, and restored exactly when a
// proposal is rejected (pbrt-v3, section 16.4, MLTSampler).
#pragma once

#include "freezeray/random.hpp"
#include "freezeray/ch04/sample_stream.hpp"

#include <cstdint>
#include <vector>

namespace freezeray::ch05 {

// BOOK(primary-sample)
struct PrimarySample {
    float value = 0.0f;
    std::uint64_t last_modified = 0;  // the iteration that last changed `value`
    // The value and its iteration before the current proposal changed them (restored on rejection).
    float backup_value = 0.0f;
    std::uint64_t backup_modified = 0;
};
// END BOOK

class PrimarySamples final : public ch04::SampleStream {
public:
    // `random` drives every mutation; sigma is the small steps' standard deviation; stream_count
    // the number of streams the sample reads (interleaved, so that they never shift each other).
    PrimarySamples(PCG32 random, float sigma, float large_step_probability, int stream_count);

    // Starts the next proposal: a large step (every number drawn afresh) with probability
    // large_step_probability, else small steps of the numbers the sample reads.
    void start_iteration();
    // Keeps the proposal as the chain's new state.
    void accept();
    // Discards the proposal: every number it changed gets back its value and iteration.
    void reject();

    float next_float() override;
    void start_stream(int index) override;

    // Continues with another generator (a chain's own, after its start from a bootstrap sample).
    void set_random(PCG32 random) { random_ = random; }

    bool large_step() const { return large_step_; }
    std::uint64_t iteration() const { return iteration_; }
    // The numbers read so far (for tests: a rejected proposal restores them exactly).
    const std::vector<PrimarySample>& samples() const { return samples_; }

private:
    // Brings sample `index` up to date for the current iteration (creating it if needed).
    void ensure_ready(std::size_t index);

    PCG32 random_;
    float sigma_;
    float large_step_probability_;
    int stream_count_;
    std::vector<PrimarySample> samples_;
    std::uint64_t iteration_ = 0;
    bool large_step_ = true;  // the first state is drawn like a large step
    std::uint64_t last_large_step_ = 0;
    int stream_ = 0;
    std::size_t stream_position_ = 0;
};

}  // namespace freezeray::ch05
