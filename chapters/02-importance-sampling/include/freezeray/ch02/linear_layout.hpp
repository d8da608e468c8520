// The row-major texture layout ("linear"), and the bilinear filter every layout shares: a
// template over the layout, so that its texel(x, y) is inlined and a lookup costs one virtual
// call (TextureStorage::lookup), not four.
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/math.hpp"
#include "freezeray/texture_storage.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace freezeray::ch02 {

// The texel index that index i (any integer) stands for in a row of n texels.
// BOOK(wrap-texel-index)
inline int wrap_texel_index(int i, int n, WrapMode wrap) {
    // Inside the image every mode leaves the index alone: the usual case, without the divisions
    // below (two or three integer divisions per index, eight or more per bilinear lookup, cost
    // more than the lookup's reads of memory; chapter 08 measured it).
    if (i >= 0 && i < n) return i;
    switch (wrap) {
        case WrapMode::Repeat: return ((i % n) + n) % n;  // C++'s % keeps the sign of i
        case WrapMode::Clamp: return std::clamp(i, 0, n - 1);
        case WrapMode::Mirror: {
            // Mirrored repetition has period 2n: n texels forwards, then the same n backwards.
            const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
            return m < n ? m : 2 * n - 1 - m;
        }
    }
    return 0;
}
// END BOOK

// Moves a coordinate by whole periods of the wrap mode (which changes nothing) so that texel
// indices computed from it stay small: a uv of 1e9 would overflow an int. A coordinate that
// is not a number reads the texture at 0.
inline float reduce_to_one_period(float u, WrapMode wrap) {
    if (!std::isfinite(u)) return 0.0f;
    switch (wrap) {
        case WrapMode::Repeat: return u - std::floor(u);
        case WrapMode::Mirror: return u - 2.0f * std::floor(0.5f * u);
        case WrapMode::Clamp: return std::clamp(u, -1.0f, 2.0f);
    }
    return u;
}

// The bilinearly filtered value of `storage` at uv. Texel (x, y) covers [x, x+1] x [y, y+1] in
// texel units, so its centre is at (x + 1/2, y + 1/2); v is flipped so that v = 0 is the
// bottom row of the image, as OBJ texture coordinates expect. (Heckbert, "What Are the
// Coordinates of a Pixel?", Graphics Gems, 1990; Pharr, Jakob and Humphreys, "Physically Based
// Rendering", 4th ed., section 10.4.) Layout is the concrete (final) storage class.
// BOOK(bilinear-lookup)
template <typename Layout>
Spectrum bilinear_lookup(const Layout& storage, const Vec2& uv, WrapMode wrap) {
    const int width = storage.width();
    const int height = storage.height();
    // Continuous texel coordinates: texel centres sit at half-integers, so subtracting 1/2
    // puts them on integers. Rows count down from the top of the image while v counts up.
    const float x = reduce_to_one_period(uv.x, wrap) * static_cast<float>(width) - 0.5f;
    const float y = (1.0f - reduce_to_one_period(uv.y, wrap)) * static_cast<float>(height) - 0.5f;
    const float x0 = std::floor(x);
    const float y0 = std::floor(y);
    const float dx = x - x0;  // weight of the right-hand column
    const float dy = y - y0;  // weight of the lower row

    const int left = wrap_texel_index(static_cast<int>(x0), width, wrap);
    const int right = wrap_texel_index(static_cast<int>(x0) + 1, width, wrap);
    const int top = wrap_texel_index(static_cast<int>(y0), height, wrap);
    const int bottom = wrap_texel_index(static_cast<int>(y0) + 1, height, wrap);

    return (1.0f - dx) * (1.0f - dy) * storage.texel(left, top) + dx * (1.0f - dy) * storage.texel(right, top) +
           (1.0f - dx) * dy * storage.texel(left, bottom) + dx * dy * storage.texel(right, bottom);
}
// END BOOK

// Row-major layout ("linear"): texel (x, y) is element y * width + x, as the image file stores it.
class LinearTextureStorage final : public TextureStorage {
public:
    explicit LinearTextureStorage(const Image& image) : TextureStorage(image), texels_(image.pixels()) {}

    Spectrum texel(int x, int y) const override {
        return texels_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width()) + static_cast<std::size_t>(x)];
    }

    // Chapter 02 has no MIP levels: every lookup reads level 0 at the point, whatever the footprint.
    Spectrum lookup(const TextureLookup& lookup, WrapMode wrap) const override {
        return bilinear_lookup(*this, lookup.uv, wrap);
    }

    std::size_t memory_bytes() const override { return texels_.size() * sizeof(Spectrum); }
    std::string description() const override { return "linear, float, 1 level"; }

private:
    std::vector<Spectrum> texels_;
};

}  // namespace freezeray::ch02
