// The settings of chapter 08's texture layouts, from the scene's "textures" block or the command
// line: how lookups filter, how texels are kept, and the tiles' size.
#pragma once

#include "freezeray/parameters.hpp"

#include <string>

namespace freezeray::ch08 {

// bilinear: level 0 only, as chapter 02 (the footprint is ignored). trilinear: the two MIP levels
// around the footprint's, each bilinearly, blended by the fraction of the level.
enum class TextureFilter { Bilinear, Trilinear };

// auto: bytes when the image came from an 8-bit file (texel_format.hpp), else floats. float:
// always floats (what chapter 02 stores; the layouts can then be compared on the same bytes).
enum class TexelFormatChoice { Auto, Float };

struct TextureLayoutSettings {
    TextureFilter filter = TextureFilter::Trilinear;
    TexelFormatChoice format = TexelFormatChoice::Auto;
    int tile_size = 4;  // texels on a tile's side (the tiled layout): 2, 4, 8, 16 or 32
};

// The tile sizes the tiled layout is compiled for (make_tiled_storage dispatches on them).
constexpr bool is_valid_tile_size(int size) { return size == 2 || size == 4 || size == 8 || size == 16 || size == 32; }

// Reads "filter", "texel_format" and "tile_size"; an InputError at the key for a value outside
// their choices.
TextureLayoutSettings read_texture_layout_settings(const Parameters& parameters);

}  // namespace freezeray::ch08
