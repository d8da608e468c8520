// Strategy images and their grid (book chapter 04).
#include "freezeray/ch04/strategy_images.hpp"

#include "freezeray/error.hpp"

#include <filesystem>

#include <algorithm>
#include <string>

namespace freezeray::ch04 {

StrategyLayers::StrategyLayers(int max_depth) : length_(std::clamp(max_depth, 1, MaxStrategyImageLength)) {
    strategies_ = index(length_, 1) + 1;  // the last strategy of the longest length is (length, 1)
}

namespace {

// A grid of equally sized tiles, one row per path length, one column per s.
Image strategy_grid(const std::vector<Image>& tiles_by_strategy, int length, int width, int height) {
    Image grid((length + 1) * width, length * height);
    for (int row = 1, k = 0; row <= length; ++row)
        for (int s = 0; s <= row; ++s, ++k) {
            const Image& tile = tiles_by_strategy[static_cast<std::size_t>(k)];
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x) grid.at(s * width + x, (row - 1) * height + y) = tile.at(x, y);
        }
    return grid;
}

}  // namespace

std::vector<std::pair<std::string, Image>> StrategyLayers::named_images(const std::vector<Image>& layers) const {
    std::vector<std::pair<std::string, Image>> images;
    if (static_cast<int>(layers.size()) < layer_count() || layers.empty()) return images;
    std::vector<Image> weighted, unweighted;
    for (int length = 1; length <= length_; ++length)
        for (int s = 0; s <= length; ++s) {
            const int t = length + 1 - s;
            std::string name = "s";  // "s1-t2" (built by appending: GCC 12 warns falsely on "s" + string)
            name += std::to_string(s);
            name += "-t";
            name += std::to_string(t);
            weighted.push_back(layers[static_cast<std::size_t>(weighted_layer(s, t) - 1)]);
            unweighted.push_back(layers[static_cast<std::size_t>(unweighted_layer(s, t) - 1)]);
            images.emplace_back(name + "-weighted.exr", weighted.back());
            images.emplace_back(name + "-unweighted.exr", unweighted.back());
        }
    images.emplace_back("longer-weighted.exr", layers[static_cast<std::size_t>(layer_count() - 1)]);
    const int width = layers[0].width(), height = layers[0].height();
    images.emplace_back("grid-weighted.png", strategy_grid(weighted, length_, width, height));
    images.emplace_back("grid-unweighted.png", strategy_grid(unweighted, length_, width, height));
    return images;
}

void check_strategy_images_folder(const std::string& folder_name, const std::string& where) {
    const std::filesystem::path folder(folder_name);
    std::error_code error;
    if (std::filesystem::exists(folder, error) && !std::filesystem::is_directory(folder, error))
        throw InputError(where, folder_name + " is a file, not a folder");
    std::filesystem::path probe = folder / "grid-weighted.png";
    if (!std::filesystem::exists(folder, error)) {  // the nearest folder that exists will hold it
        std::filesystem::path parent = folder;
        do parent = parent.has_parent_path() ? parent.parent_path() : std::filesystem::path(".");
        while (!std::filesystem::exists(parent, error) && parent != ".");
        probe = parent / "strategy-images-probe.png";
    }
    check_image_writable(probe.string());
}

}  // namespace freezeray::ch04
