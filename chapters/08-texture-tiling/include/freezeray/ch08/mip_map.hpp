// MIP maps (Williams, "Pyramidal Parametrics", 1983): the image averaged down by two, again and
// again, to a single texel. A pixel that covers many texels reads a level where one texel is
// about a pixel's size, instead of four texels of level 0 picked nearly at random (aliasing) from
// far apart in memory (where no layout keeps them together).
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/math.hpp"

#include <functional>
#include <vector>

namespace freezeray::ch08 {

// The next level of `level`: max(1, floor(w / 2)) x max(1, floor(h / 2)) texels, each the
// exact average of the part of `level` it covers (a box filter). Texel i of n' = floor(n / 2)
// covers [i n / n', (i + 1) n / n') of the n texels below: exactly two when n is even, and
// parts of three when n is odd, weighted by how much of each it covers, so that any size, not
// only powers of two, keeps its mean (the weights are those of NVIDIA's "Non-Power-of-Two
// Mipmap Creation", 2005, and of any exact area average). Along each axis on its own: a texel of
// the next level is the sum over the texels below of (the length of x's overlap with its
// interval / the interval's length) x (the same for y) x the texel below; a side of 1 stays 1
// (its one texel covers the whole side). The sums are made in double precision and rounded to
// float once, so that a constant image stays that constant and the mean is kept to rounding.
Image next_mip_level(const Image& level);

// Calls `visit` with level 1, 2, ... of `image` down to the 1 x 1 level, in that order, each
// made from the one before: only two levels are held at a time.
void for_each_mip_level(const Image& image, const std::function<void(const Image& level)>& visit);

// Level 0 (the image) and every level after it, down to 1 x 1: 1 + floor(log2(max(w, h))) levels
// (for_each_mip_level's, the very loop the layouts store).
std::vector<Image> build_mip_pyramid(const Image& image);

// The MIP level for a pixel's footprint (duv_dx, duv_dy) on a texture of width x height texels:
// log2 of the longer of the two steps, measured in texels of level 0 (OpenGL 4.6 core profile
// specification, section 8.14.1, equations 8.4 to 8.7). Negative where a texel is larger than
// a pixel (magnification); zero for a zero footprint (nothing known: a point lookup).
float mip_level(const Vec2& duv_dx, const Vec2& duv_dy, int width, int height);

}  // namespace freezeray::ch08
