// Texture storage: the size and range every layout keeps.
#include "freezeray/texture_storage.hpp"

#include <stdexcept>

namespace freezeray {

TextureStorage::TextureStorage(const Image& image)
    : width_(image.width()), height_(image.height()), minimum_(0.0f), maximum_(0.0f) {
    // An empty image is a programming error: read_image refuses files without pixels.
    if (image.pixel_count() == 0) throw std::invalid_argument("TextureStorage: the image has no pixels");
    minimum_ = maximum_ = image.pixels().front();
    for (const Spectrum& texel : image.pixels()) {
        minimum_ = glm::min(minimum_, texel);
        maximum_ = glm::max(maximum_, texel);
    }
}

}  // namespace freezeray
