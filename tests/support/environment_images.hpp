// Environment maps for tests of chapter 03's environment light, shared by the chi2 and unit
// tests: each is made to stress one thing the sampling density has to handle.
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/random.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace freezeray::testing {

// A 32 x 16 map of varied colours (luminance from 0 to about 1, cubed for contrast), black at the
// top three rows and along row 11, with a few black pixels: every kind of row the density has to
// handle.
inline Image varied_environment_image() {
    Image image(32, 16);
    PCG32 random(31, 7);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x) {
            const float a = random.next_float(), b = random.next_float(), c = random.next_float();
            image.at(x, y) = (y < 3 || y == 11 || (x * 7 + y) % 13 == 0) ? Spectrum(0.0f) : Spectrum(a * a * a, b, c * c);
        }
    return image;
}

// A rotation by `degrees` about `axis` (for an environment's light-to-world frame).
inline Mat3 rotation(float degrees, const Vec3& axis) {
    return Mat3(glm::rotate(Mat4(1.0f), glm::radians(degrees), glm::normalize(axis)));
}

}  // namespace freezeray::testing
