// Chapter 08's texture storage: MIP levels, each in a memory layout (row-major or tiled) and a
// texel format (floats or bytes), looked up with the bilinear filter of chapter 02 on one level,
// or trilinearly between two. The layout and the format are template parameters, so a lookup
// computes its addresses with constants and decodes inline, behind one virtual call.
#pragma once

#include "freezeray/cache_line_allocator.hpp"
#include "freezeray/ch02/linear_layout.hpp"
#include "freezeray/ch08/mip_map.hpp"
#include "freezeray/ch08/texture_layout_settings.hpp"
#include "freezeray/image.hpp"
#include "freezeray/texture_storage.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace freezeray::ch08 {

// One texel a lookup read: its level and its column and row there.
struct TexelRead {
    int level;
    int x;
    int y;
};

// What every chapter 08 storage tells tests, `info` and the benchmark, whatever its layout.
class MipMappedTexture : public TextureStorage {
public:
    int level_count() const { return static_cast<int>(sizes_.size()); }
    int level_width(int level) const { return sizes_[static_cast<std::size_t>(level)].first; }
    int level_height(int level) const { return sizes_[static_cast<std::size_t>(level)].second; }
    // Texel (x, y) of `level`, decoded; 0 <= x < level_width(level), 0 <= y < level_height(level).
    virtual Spectrum level_texel(int level, int x, int y) const = 0;
    // The bilinearly filtered value of one level at uv (what a trilinear lookup blends).
    virtual Spectrum level_lookup(int level, const Vec2& uv, WrapMode wrap) const = 0;
    // A lookup that also appends every texel it reads to `reads` (for texture-benchmark's cache
    // model and access maps).
    virtual Spectrum lookup_recording_reads(const TextureLookup& lookup, WrapMode wrap,
                                            std::vector<TexelRead>& reads) const = 0;
    // The cache line (address / 64) that holds texel (x, y) of `level`.
    virtual std::uintptr_t cache_line(int level, int x, int y) const = 0;
    TextureFilter filter() const { return filter_; }

protected:
    MipMappedTexture(const Image& image, TextureFilter filter) : TextureStorage(image), filter_(filter) {}
    std::vector<std::pair<int, int>> sizes_;  // of each level, set by the layout's constructor

private:
    TextureFilter filter_;
};

// One MIP level: its texels encoded in Format, at the indices Addressing gives them.
template <typename Addressing, typename Format>
class TexelLevel {
public:
    // Every texel of `image`, encoded (rounded to the format's nearest value).
    TexelLevel(const Image& image, const Format& format) : TexelLevel(image.width(), image.height(), format) {
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_; ++x) texels_[addressing_.index(x, y)] = format_.encode(image.at(x, y));
    }

    // `image` in a format that must hold every texel exactly (bit for bit), or nothing from the
    // first texel it does not: deciding on the format and encoding are one pass over the image.
    static std::optional<TexelLevel> encode_exactly(const Image& image, const Format& format) {
        TexelLevel level(image.width(), image.height(), format);
        for (int y = 0; y < level.height_; ++y)
            for (int x = 0; x < level.width_; ++x) {
                const auto stored = level.format_.encode_exactly(image.at(x, y));
                if (!stored) return std::nullopt;
                level.texels_[level.addressing_.index(x, y)] = *stored;
            }
        return level;
    }

    // What chapter 02's bilinear_lookup<Layout> reads.
    int width() const { return width_; }
    int height() const { return height_; }
    Spectrum texel(int x, int y) const { return format_.decode(texels_[addressing_.index(x, y)]); }

    std::size_t memory_bytes() const { return texels_.size() * sizeof(typename Format::Stored); }
    const Format& format() const { return format_; }
    // Where texel (x, y) lies in memory (for the access heat map).
    const void* address(int x, int y) const { return &texels_[addressing_.index(x, y)]; }

private:
    TexelLevel(int width, int height, const Format& format)
        : width_(width), height_(height), addressing_(width, height), format_(format),
          texels_(addressing_.texel_count(width, height)) {}

    int width_;
    int height_;
    Addressing addressing_;
    Format format_;
    std::vector<typename Format::Stored, CacheLineAllocator<typename Format::Stored>> texels_;
};

// The trilinear filter over any levels: level_at(k) gives what chapter 02's bilinear_lookup reads
// for level k (a TexelLevel, or a view of it that records the memory it touches).
// BOOK(trilinear-lookup)
template <typename LevelAt>
Spectrum trilinear_lookup(const TextureLookup& lookup, WrapMode wrap, int width, int height, int level_count,
                          const LevelAt& level_at) {
    const int last = level_count - 1;
    const float level = mip_level(lookup.duv_dx, lookup.duv_dy, width, height);
    // Magnified, a point, or no MIP levels: level 0, as chapter 02 (a NaN level lands here too).
    if (!(level > 0.0f) || last == 0) return ch02::bilinear_lookup(level_at(0), lookup.uv, wrap);
    if (level >= static_cast<float>(last)) return ch02::bilinear_lookup(level_at(last), lookup.uv, wrap);
    const int below = static_cast<int>(level);
    const float t = level - static_cast<float>(below);  // how far towards the coarser level
    const Spectrum fine = ch02::bilinear_lookup(level_at(below), lookup.uv, wrap);
    if (t == 0.0f) return fine;
    const Spectrum coarse = ch02::bilinear_lookup(level_at(below + 1), lookup.uv, wrap);
    return (1.0f - t) * fine + t * coarse;
}
// END BOOK

// A level that notes every texel read from it, and returns the level's texel.
template <typename Level>
struct ReadRecorder {
    const Level& level;
    int index;  // the level's
    std::vector<TexelRead>& reads;
    int width() const { return level.width(); }
    int height() const { return level.height(); }
    Spectrum texel(int x, int y) const {
        reads.push_back({index, x, y});
        return level.texel(x, y);
    }
};

template <typename Addressing, typename Format>
class MipMappedStorage final : public MipMappedTexture {
public:
    // `image` with its level 0 already encoded (in `format`); with the trilinear filter, every
    // level of the pyramid, with the bilinear one, level 0 only.
    MipMappedStorage(const Image& image, TexelLevel<Addressing, Format> level0, TextureFilter filter)
        : MipMappedTexture(image, filter) {
        const Format format = level0.format();
        levels_.push_back(std::move(level0));
        // Each level is encoded as soon as it is made (for_each_mip_level keeps only the one below
        // the next in floats): an 8192^2 texture needs its 768 MiB image and 192 MiB more, not the
        // whole pyramid in floats.
        if (filter == TextureFilter::Trilinear)
            for_each_mip_level(image, [&](const Image& level) { levels_.emplace_back(level, format); });
        for (const auto& level : levels_) sizes_.emplace_back(level.width(), level.height());
    }

    Spectrum texel(int x, int y) const override { return levels_.front().texel(x, y); }
    Spectrum level_texel(int level, int x, int y) const override {
        return levels_[static_cast<std::size_t>(level)].texel(x, y);
    }
    Spectrum level_lookup(int level, const Vec2& uv, WrapMode wrap) const override {
        return ch02::bilinear_lookup(levels_[static_cast<std::size_t>(level)], uv, wrap);
    }
    const TexelLevel<Addressing, Format>& level(int level) const { return levels_[static_cast<std::size_t>(level)]; }

    Spectrum lookup(const TextureLookup& lookup, WrapMode wrap) const override {
        return trilinear_lookup(lookup, wrap, width(), height(), static_cast<int>(levels_.size()),
                                [this](int level) -> const auto& { return levels_[static_cast<std::size_t>(level)]; });
    }

    Spectrum lookup_recording_reads(const TextureLookup& lookup, WrapMode wrap,
                                    std::vector<TexelRead>& reads) const override {
        return trilinear_lookup(lookup, wrap, width(), height(), static_cast<int>(levels_.size()), [&](int level) {
            return ReadRecorder<TexelLevel<Addressing, Format>>{levels_[static_cast<std::size_t>(level)], level, reads};
        });
    }
    std::uintptr_t cache_line(int level, int x, int y) const override {
        return reinterpret_cast<std::uintptr_t>(levels_[static_cast<std::size_t>(level)].address(x, y)) / CacheLineBytes;
    }

    std::size_t memory_bytes() const override {
        std::size_t bytes = 0;
        for (const auto& level : levels_) bytes += level.memory_bytes();
        return bytes;
    }

    std::string description() const override {
        std::string layout = Addressing::name;
        if constexpr (requires { Addressing::tile_size; })
            layout += " (" + std::to_string(Addressing::tile_size) + " x " + std::to_string(Addressing::tile_size) + ")";
        std::string format = Format::name;
        if constexpr (requires(Format f) { f.decoding; }) format += std::string(" ") + levels_.front().format().decoding->name;
        return layout + ", " + format + ", " + std::to_string(levels_.size()) + (levels_.size() == 1 ? " level" : " levels");
    }

private:
    std::vector<TexelLevel<Addressing, Format>> levels_;
};

// Stores `image` with the layout Addressing as `settings` say: bytes when the format is auto and
// the image allows them exactly, floats otherwise.
std::shared_ptr<const TextureStorage> make_row_major_storage(const Image& image, const TextureLayoutSettings& settings);
std::shared_ptr<const TextureStorage> make_tiled_storage(const Image& image, const TextureLayoutSettings& settings);

}  // namespace freezeray::ch08
