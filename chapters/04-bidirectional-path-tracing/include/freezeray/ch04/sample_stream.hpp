// Where a path's random numbers come from: independent uniform numbers (PCG32) for the
// integrators of chapters 01 to 04, or the primary samples that a Markov chain mutates
// (chapter 05, Kelemen et al. 2002). Bidirectional path tracing reads its numbers through this
// interface so that Metropolis light transport can drive the very same code.
#pragma once

#include "freezeray/math.hpp"
#include "freezeray/random.hpp"

namespace freezeray::ch04 {

class SampleStream {
public:
    virtual ~SampleStream() = default;

    // The next number in [0, 1).
    virtual float next_float() = 0;

    // The next pair, for a 2D draw (a point on a light, a BSDF direction), so that a sampler
    // that stratifies pairs (chapter 09) can give one. By default two numbers, the second drawn
    // first: the order in which g++ evaluated Vec2(next_float(), next_float()) in this chapter's
    // code before there was a pair, kept so that images stay bit for bit what they were.
    virtual Vec2 next_2d() {
        const float second = next_float();
        const float first = next_float();
        return Vec2(first, second);
    }

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
