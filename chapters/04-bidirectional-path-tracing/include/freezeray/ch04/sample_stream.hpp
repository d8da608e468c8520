// Where a path's random numbers come from: independent uniform numbers (PCG32) for the
// integrators of chapters 01 to 04, or the primary samples that a Markov chain mutates
// (chapter 05, Kelemen et al. 2002). Bidirectional path tracing reads its numbers through this
// interface so that Metropolis light transport can drive the very same code.
#pragma once

#include "freezeray/random.hpp"

namespace freezeray::ch04 {

class SampleStream {
public:
    virtual ~SampleStream() = default;

    // The next number in [0, 1).
    virtual float next_float() = 0;

    // Switches to stream `index` and restarts it: numbers of different streams never shift one
    // another (a longer camera subpath does not change the light subpath's numbers). Used by
    // primary-sample-space MLT; independent numbers ignore it.
    virtual void start_stream(int index) { (void)index; }
};

// Independent uniform numbers from a PCG32 generator.
class IndependentSamples final : public SampleStream {
public:
    explicit IndependentSamples(PCG32& random) : random_(random) {}
    float next_float() override { return random_.next_float(); }

private:
    PCG32& random_;
};

}  // namespace freezeray::ch04
