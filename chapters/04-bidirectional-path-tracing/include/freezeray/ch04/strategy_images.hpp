// The images of bidirectional path tracing's strategies, one per (s, t), weighted and
// unweighted, and the grid that lays them out by path length (Veach 1997, figure 10.3; Veach and
// Guibas 1995, figure 2): what each strategy is good at, and what MIS keeps of it.
#pragma once

#include "freezeray/image.hpp"

#include <string>
#include <utility>
#include <vector>

namespace freezeray::ch04 {

// Paths up to this many segments get images of their own; longer ones share one weighted image,
// so that the weighted images always add up to the render.
inline constexpr int MaxStrategyImageLength = 5;

// The splat layers (SplatBuffer::add_splat) of the strategy images for renders of max_depth:
// 1 + 2 k for strategy k's weighted image, 2 + 2 k for its unweighted one, and one last layer
// for the weighted contributions of longer paths.
class StrategyLayers {
public:
    explicit StrategyLayers(int max_depth);

    // The number of strategies with images: (s, t) with t >= 1 and 1 <= s + t - 1 <= length.
    int strategies() const { return strategies_; }
    int layer_count() const { return 2 * strategies_ + 1; }
    bool has_image(int s, int t) const { return s + t - 1 <= length_; }
    int weighted_layer(int s, int t) const { return has_image(s, t) ? 1 + 2 * index(s, t) : layer_count(); }
    int unweighted_layer(int s, int t) const { return has_image(s, t) ? 2 + 2 * index(s, t) : 0; }

    // Names the images made from the layers (index 0 for layer 1): s{s}-t{t}-weighted.exr,
    // s{s}-t{t}-unweighted.exr, longer-weighted.exr, and the grids grid-weighted.png and
    // grid-unweighted.png (rows: path length 1, 2, ...; columns: s = 0, 1, ...).
    std::vector<std::pair<std::string, Image>> named_images(const std::vector<Image>& layers) const;

private:
    // Strategies ordered by length, then s: (0, 2), (1, 1), (0, 3), (1, 2), (2, 1), ...
    int index(int s, int t) const {
        const int length = s + t - 1;
        return (length - 1) * (length + 2) / 2 + s;
    }

    int length_;
    int strategies_;
};

// Checks, before a render, that `folder` (given by the option at `where`) can take the strategy
// images: it is a folder, or does not exist yet and the nearest existing folder above it takes
// files. The folder itself is made after the render, so a failed render leaves nothing behind.
void check_strategy_images_folder(const std::string& folder, const std::string& where);

}  // namespace freezeray::ch04
