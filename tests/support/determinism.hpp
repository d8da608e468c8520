// Checks of the determinism promise (DESIGN.md, "Determinism"): an image depends on the seed,
// never on the number of threads.
#pragma once

#include "freezeray/image.hpp"
#include "test_scenes.hpp"

namespace freezeray::testing {

// Whether the two images have the same size and the same floats, bit for bit.
bool bit_identical(const Image& a, const Image& b);

// Renders `request` with 1 and with 2 threads and CHECKs that the images (and the variances,
// when the integrator estimates them) are bit-identical; then CHECKs that the next seed gives
// another image, so that a renderer ignoring its seed cannot pass.
void check_thread_count_independent(TestRender request);

}  // namespace freezeray::testing
