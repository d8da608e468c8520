// Where texel (x, y) of a width x height image lies in memory: its index in the array of texels.
// The row-major order of an image file puts texels (x, y) and (x, y + 1) a whole row apart, so a
// bilinear lookup, which reads both, touches two cache lines, and a ray hitting a texture at
// nearby points of successive rows touches many. Tiles keep a small square of texels together:
// (Pharr and Humphreys, "Physically Based Rendering", 3rd ed., 2016, section A.4.4, BlockedArray;
// Hakura and Gupta, "The Design and Analysis of a Cache Architecture for Texture Mapping", 1997).
#pragma once

#include <cstddef>

namespace freezeray::ch08 {

// Row-major ("linear"): texel (x, y) at y * width + x.
class RowMajorAddressing {
public:
    static constexpr const char* name = "linear";

    RowMajorAddressing(int width, int /*height*/) : width_(static_cast<std::size_t>(width)) {}

    // How many texels the array holds: exactly width x height.
    std::size_t texel_count(int width, int height) const {
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    }
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width_ + static_cast<std::size_t>(x); }

private:
    std::size_t width_;
};

// The index of texel (x, y) when the image is cut into square tiles of 2^tile_log2 texels on a
// side, `tiles_per_row` tiles across: the tiles follow one another in row-major order, and the
// texels of a tile, 2^(2 tile_log2) of them, too. Shifts and masks, no division.
// BOOK(tiled-index)
inline std::size_t tiled_index(int x, int y, int tile_log2, std::size_t tiles_per_row) {
    // EXERCISE(ch08/tile-offset): the offset of texel (x, y) in the tiled layout of book chapter 08, "Where a texel lives": tiles of 2^tile_log2 texels on a side in row order, texels in row order within a tile
    const std::size_t mask = (std::size_t{1} << tile_log2) - 1;
    const std::size_t tile_x = static_cast<std::size_t>(x) >> tile_log2;
    const std::size_t tile_y = static_cast<std::size_t>(y) >> tile_log2;
    const std::size_t tile = tile_y * tiles_per_row + tile_x;
    const std::size_t offset = ((static_cast<std::size_t>(y) & mask) << tile_log2) + (static_cast<std::size_t>(x) & mask);
    return (tile << (2 * tile_log2)) + offset;
    // END EXERCISE
}
// END BOOK

// Tiles of 2^TileLog2 x 2^TileLog2 texels. The image is padded to whole tiles: the padding
// texels are never read (a lookup asks only for 0 <= x < width, 0 <= y < height).
template <int TileLog2>
class TiledAddressing {
public:
    static constexpr int tile_size = 1 << TileLog2;
    static constexpr const char* name = "tiled";

    TiledAddressing(int width, int /*height*/) : tiles_per_row_(tiles_for(width)) {}

    std::size_t texel_count(int width, int height) const {
        return tiles_for(width) * tiles_for(height) * static_cast<std::size_t>(tile_size * tile_size);
    }
    std::size_t index(int x, int y) const { return tiled_index(x, y, TileLog2, tiles_per_row_); }

private:
    static std::size_t tiles_for(int texels) { return (static_cast<std::size_t>(texels) + tile_size - 1) >> TileLog2; }

    std::size_t tiles_per_row_;
};

}  // namespace freezeray::ch08
