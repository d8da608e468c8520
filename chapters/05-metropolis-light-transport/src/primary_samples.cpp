// Primary samples: lazy extension, small and large steps, backup and restore (book chapter 05;
// Kelemen et al. 2002; pbrt-v3, section 16.4).
#include "freezeray/ch05/primary_samples.hpp"

#include "freezeray/math.hpp"
#include "freezeray/ch05/metropolis.hpp"

#include <cmath>

namespace freezeray::ch05 {

PrimarySamples::PrimarySamples(PCG32 random, float sigma, float large_step_probability, int stream_count)
    : random_(random), sigma_(sigma), large_step_probability_(large_step_probability), stream_count_(stream_count) {}

void PrimarySamples::start_iteration() {
    ++iteration_;
    large_step_ = random_.next_float() < large_step_probability_;
}

void PrimarySamples::start_stream(int index) {
    stream_ = index;
    stream_position_ = 0;
}

float PrimarySamples::next_float() {
    const std::size_t index = static_cast<std::size_t>(stream_) +
                              static_cast<std::size_t>(stream_count_) * stream_position_++;
    ensure_ready(index);
    return samples_[index].value;
}

// BOOK(ensure-ready)
void PrimarySamples::ensure_ready(std::size_t index) {
    if (index >= samples_.size()) {
        // A number no earlier state read: the current state does not depend on it, so it starts
        // as a fresh uniform number (its distribution under the target is still uniform).
        const std::size_t old_size = samples_.size();
        samples_.resize(index + 1);
        for (std::size_t i = old_size; i <= index; ++i) {
            samples_[i].value = random_.next_float();
            samples_[i].last_modified = iteration_;
            samples_[i].backup_value = samples_[i].value;
            samples_[i].backup_modified = iteration_;
        }
        return;
    }
    PrimarySample& x = samples_[index];
    if (x.last_modified == iteration_) return;  // already mutated in this proposal
    // An accepted large step since this number was last read replaced every number: draw it.
    if (x.last_modified < last_large_step_) {
        x.value = random_.next_float();
        x.last_modified = last_large_step_;
    }
    x.backup_value = x.value;
    x.backup_modified = x.last_modified;
    if (large_step_) {
        x.value = random_.next_float();
    } else {
        // The small steps of every iteration since it was last read, as one (their sum is
        // normal with variance sigma^2 times their count). Box-Muller for the normal sample.
        const float u1 = 1.0f - random_.next_float();  // in (0, 1]
        const float u2 = random_.next_float();
        const float normal = std::sqrt(-2.0f * std::log(u1)) * std::cos(2.0f * Pi * u2);
        x.value = small_step(x.value, normal, sigma_, iteration_ - x.last_modified);
    }
    x.last_modified = iteration_;
}
// END BOOK

void PrimarySamples::accept() {
    if (large_step_) last_large_step_ = iteration_;
}

// BOOK(reject)
void PrimarySamples::reject() {
    for (PrimarySample& x : samples_)
        if (x.last_modified == iteration_) {
            x.value = x.backup_value;
            x.last_modified = x.backup_modified;
        }
    --iteration_;  // the rejected proposal never happened: the next one reuses its number
}
// END BOOK

}  // namespace freezeray::ch05
