// The two rules of a Metropolis-Hastings chain in primary sample space (Metropolis et al. 1953;
// Hastings 1970; Kelemen, Szirmay-Kalos, Antal and Csonka 2002): how a proposal is made from the
// current state, and with what probability it is accepted.
#pragma once

#include <cstdint>

namespace freezeray::ch05 {

// The acceptance probability of a symmetric proposal (Metropolis et al. 1953): the target
// function's value at the proposed state over its value at the current state, at most 1. A
// current state of value 0 (a chain that has not found light yet) accepts anything.
float acceptance_probability(float current, float proposed);

// A small step of one primary sample (Kelemen et al. 2002, section 4): value moved by a normal
// sample times sigma, wrapped around into [0, 1) so that the step is symmetric. `steps` small
// steps not applied yet (the sample was not read for that many iterations) add up to one step of
// deviation sigma sqrt(steps) (pbrt-v3, section 16.4).
float small_step(float value, float normal_sample, float sigma, std::uint64_t steps);

}  // namespace freezeray::ch05
