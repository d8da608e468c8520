// Building MIP levels and choosing one.
#include "freezeray/ch08/mip_map.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch08 {

// BOOK(next-mip-level)
Image next_mip_level(const Image& level) {
    // EXERCISE(ch08/mip-pyramid): the next level of the pyramid of book chapter 08, "MIP maps, because locality needs them", as next_mip_level's comment in mip_map.hpp states it: its size, and every texel the exact average of the part of the level below it covers, for any size, even or odd
    // For each of the n' texels of the next level, along one axis: the texels below it and their
    // weights (the length of [i, i + 1) inside the texel's interval, divided by its length n / n').
    struct Taps {
        int first = 0;
        int count = 0;
        double weight[3] = {0.0, 0.0, 0.0};
    };
    auto box_taps = [](int n) {
        const int next = std::max(1, n / 2);
        std::vector<Taps> taps(static_cast<std::size_t>(next));
        for (int i = 0; i < next; ++i) {
            // The interval [a, b) in texels below: a = i n / n', b = (i + 1) n / n'.
            const double a = static_cast<double>(i) * n / next;
            const double b = static_cast<double>(i + 1) * n / next;
            Taps& t = taps[static_cast<std::size_t>(i)];
            t.first = static_cast<int>(std::floor(a));
            const int last = std::min(n - 1, static_cast<int>(std::ceil(b)) - 1);
            t.count = last - t.first + 1;
            for (int k = 0; k < t.count; ++k) {
                const double lo = std::max(a, static_cast<double>(t.first + k));
                const double hi = std::min(b, static_cast<double>(t.first + k + 1));
                t.weight[k] = (hi - lo) / (b - a);
            }
        }
        return taps;
    };
    const std::vector<Taps> across = box_taps(level.width());
    const std::vector<Taps> down = box_taps(level.height());
    Image next(static_cast<int>(across.size()), static_cast<int>(down.size()));
    if (level.width() % 2 == 0 && level.height() % 2 == 0) {
        // Even sizes: each texel is the mean of two by two (the same sum as below, which would
        // weight each of the four by 1/4 exactly; this is only quicker).
        for (int y = 0; y < next.height(); ++y)
            for (int x = 0; x < next.width(); ++x) {
                const glm::dvec3 sum = glm::dvec3(level.at(2 * x, 2 * y)) + glm::dvec3(level.at(2 * x + 1, 2 * y)) +
                                       glm::dvec3(level.at(2 * x, 2 * y + 1)) + glm::dvec3(level.at(2 * x + 1, 2 * y + 1));
                next.at(x, y) = Spectrum(0.25 * sum);
            }
        return next;
    }
    for (int y = 0; y < next.height(); ++y)
        for (int x = 0; x < next.width(); ++x) {
            const Taps& row = down[static_cast<std::size_t>(y)];
            const Taps& column = across[static_cast<std::size_t>(x)];
            glm::dvec3 sum(0.0);
            for (int j = 0; j < row.count; ++j)
                for (int i = 0; i < column.count; ++i)
                    sum += row.weight[j] * column.weight[i] * glm::dvec3(level.at(column.first + i, row.first + j));
            next.at(x, y) = Spectrum(sum);
        }
    return next;
    // END EXERCISE
}
// END BOOK

void for_each_mip_level(const Image& image, const std::function<void(const Image& level)>& visit) {
    if (image.width() == 1 && image.height() == 1) return;
    Image level = next_mip_level(image);
    for (;;) {
        visit(level);
        if (level.width() == 1 && level.height() == 1) return;
        level = next_mip_level(level);
    }
}

std::vector<Image> build_mip_pyramid(const Image& image) {
    std::vector<Image> levels{image};
    for_each_mip_level(image, [&](const Image& level) { levels.push_back(level); });
    return levels;
}

// BOOK(mip-level)
float mip_level(const Vec2& duv_dx, const Vec2& duv_dy, int width, int height) {
    // EXERCISE(ch08/mip-level): the MIP level for a pixel's footprint in texture space, book chapter 08, "Choosing the level, and trilinear filtering": the longer of the two steps in texels decides it; 0 for a footprint of nothing
    const Vec2 size(static_cast<float>(width), static_cast<float>(height));
    const float rho = std::max(glm::length(duv_dx * size), glm::length(duv_dy * size));
    if (!(rho > 0.0f)) return 0.0f;
    return std::log2(rho);
    // END EXERCISE
}
// END BOOK

}  // namespace freezeray::ch08
