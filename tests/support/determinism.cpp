// Checks of the determinism promise.
#include "determinism.hpp"

#include <catch2/catch.hpp>

#include <cstring>

namespace freezeray::testing {

bool bit_identical(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixel_count() * sizeof(Spectrum)) == 0;
}

void check_thread_count_independent(TestRender request) {
    request.threads = 1;
    const RenderResult one = render(request);
    request.threads = 2;
    const RenderResult two = render(request);
    INFO(request.integrator << " on " << request.scene << ", seed " << request.seed);
    CHECK(one.samples_per_pixel == request.samples_per_pixel);
    CHECK(bit_identical(one.image, two.image));
    CHECK(bit_identical(one.variance, two.variance));
    ++request.seed;
    const RenderResult other = render(request);
    CHECK(!bit_identical(one.image, other.image));
}

}  // namespace freezeray::testing
