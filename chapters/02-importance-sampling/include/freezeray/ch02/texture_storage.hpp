// Where an image texture keeps its texels. How texels are laid out in memory is a strategy
// behind one interface: chapter 02 stores rows one after another; chapter 08 adds a tiled
// layout that keeps neighbouring texels in the same cache line, with the same interface.
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/math.hpp"

#include <memory>
#include <vector>

namespace freezeray::ch02 {

// The texels of one image: width x height linear RGB values, (0, 0) at the top-left.
class TextureStorage {
public:
    virtual ~TextureStorage() = default;

    int width() const { return width_; }
    int height() const { return height_; }

    // The texel in column x, row y; requires 0 <= x < width and 0 <= y < height.
    virtual Spectrum texel(int x, int y) const = 0;

    // The smallest and the largest texel value, per channel. Bilinear filtering mixes texels
    // with weights that sum to one, so no lookup leaves this range.
    const Spectrum& minimum() const { return minimum_; }
    const Spectrum& maximum() const { return maximum_; }

protected:
    // Every layout is made from a decoded image (at least 1 x 1) and keeps its size and range.
    explicit TextureStorage(const Image& image);

private:
    int width_;
    int height_;
    Spectrum minimum_;
    Spectrum maximum_;
};

// Row-major layout ("linear"): texel (x, y) is element y * width + x, as the image file stores it.
class LinearTextureStorage final : public TextureStorage {
public:
    explicit LinearTextureStorage(const Image& image);

    Spectrum texel(int x, int y) const override {
        return texels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width()) + static_cast<std::size_t>(x)];
    }

private:
    std::vector<Spectrum> texels_;
};

}  // namespace freezeray::ch02
