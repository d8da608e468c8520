// The Image container and the sRGB transfer function.
#include "freezeray/image.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace freezeray {

Image::Image(int width, int height, Spectrum fill) : width_(width), height_(height) {
    // Negative sizes are a programming error, not bad input: the readers check file headers first.
    if (width < 0 || height < 0) {
        throw std::invalid_argument("Image: negative size " + std::to_string(width) + "x" + std::to_string(height));
    }
    pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
}

Image::Image(int width, int height, std::vector<Spectrum> pixels)
    : width_(width), height_(height), pixels_(std::move(pixels)) {
    if (width < 0 || height < 0 || pixels_.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
        throw std::invalid_argument("Image: " + std::to_string(pixels_.size()) + " pixels for a size of " +
                                    std::to_string(width) + "x" + std::to_string(height));
    }
}

// Encodes one linear channel with the sRGB transfer function (IEC 61966-2-1:1999, section 5.2):
// a linear segment near black, then a 1/2.4 power curve. Inputs should lie in [0, 1].
float linear_to_srgb(float linear) {
    if (linear <= 0.0031308f) {
        return 12.92f * linear;
    }
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// Decodes one sRGB-encoded channel back to linear (the inverse of linear_to_srgb, same standard).
float srgb_to_linear(float encoded) {
    if (encoded <= 0.04045f) {
        return encoded / 12.92f;
    }
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace freezeray
