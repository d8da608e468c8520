// The interface of a texture's texels, whatever their layout in memory. Chapter 02 stores rows
// one after another ("linear"); chapter 08 adds tiles that keep neighbouring texels in one cache
// line. A layout is a registered capability (Registry::add_texture_layout), like an accelerator.
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/math.hpp"

#include <cstddef>
#include <string>

namespace freezeray {

class Camera;
struct Hit;
struct TriangleMesh;

// How a texture layout's lookups learn a pixel's footprint in texture space: sets the hit's
// duv_dx and duv_dy (chapter 08's ray differentials). Null for a layout that looks up at the point.
using TextureFootprint = void (*)(Hit& hit, const TriangleMesh& mesh, const Camera& camera);

// What happens to texture coordinates outside [0, 1]: the image repeats, its edge texels
// stretch out, or it repeats mirrored so that neighbouring copies meet without a seam.
enum class WrapMode { Repeat, Clamp, Mirror };

// Where a texture is looked up: the texture coordinates of a point and, when they are known, how
// they change from one pixel of the image to the next (d(u, v)/dx and d(u, v)/dy: the footprint of
// a pixel in texture space, texture_footprint.hpp). Chapter 08 chooses a MIP level from them; zero
// derivatives mean that nothing is known, and the texture is looked up at the point.
struct TextureLookup {
    Vec2 uv{0.0f};
    Vec2 duv_dx{0.0f};
    Vec2 duv_dy{0.0f};
};

// The texels of one image: width x height linear RGB values, (0, 0) at the top-left.
class TextureStorage {
public:
    virtual ~TextureStorage() = default;

    int width() const { return width_; }
    int height() const { return height_; }

    // The filtered value at lookup.uv: one virtual call per lookup, inside which a layout reads
    // its texels without further dispatch (chapter 02's bilinear_lookup<Layout>). A layout
    // without MIP levels (chapter 02's) ignores the footprint.
    virtual Spectrum lookup(const TextureLookup& lookup, WrapMode wrap) const = 0;

    // The texel in column x, row y; requires 0 <= x < width and 0 <= y < height. For tests
    // and tools; lookups call the layout's own (inline) texel.
    virtual Spectrum texel(int x, int y) const = 0;

    // The smallest and the largest texel value, per channel. Bilinear filtering mixes texels
    // with weights that sum to one, so no lookup leaves this range.
    const Spectrum& minimum() const { return minimum_; }
    const Spectrum& maximum() const { return maximum_; }

    // The bytes its texels take (padding and MIP levels included), and what `info` says of it:
    // "linear, float, 1 level", "tiled (4 x 4), 8-bit sRGB, 14 levels".
    virtual std::size_t memory_bytes() const = 0;
    virtual std::string description() const = 0;

protected:
    // Every layout is made from a decoded image (at least 1 x 1) and keeps its size and range.
    explicit TextureStorage(const Image& image);

private:
    int width_;
    int height_;
    Spectrum minimum_;
    Spectrum maximum_;
};

}  // namespace freezeray
