// A check of an OpenEXR file's structure before tinyexr reads it (see the class comment).
// Private to image_io_exr.cpp.
#pragma once

#include "freezeray/error.hpp"
#include "image_io_formats.hpp"

#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace freezeray::image_io {

// tinyexr 1.0.1 trusts much of what it reads (found by fuzz_image): a "tiles" attribute shorter
// than 9 bytes is read past its end, a tile size of 0 is divided by, a channel's pixel type
// other than 0 to 2 leaves its buffer unallocated (then freed), sampling rates are ignored, the
// tile coordinates stored in each chunk are multiplied without a check, and a "chunkCount"
// attribute sizes an allocation. This walks the header of a single-part file as the OpenEXR
// file layout describes it (attributes: name\0 type\0 size value, ended by an empty name), then
// the chunk offset table of a tiled file, and refuses what tinyexr would mishandle.
class ExrHeaderCheck {
public:
    ExrHeaderCheck(const Bytes& bytes, const std::string& path) : bytes_(bytes), path_(path) {}

    void run() {
        const bool tiled_version = (bytes_[5] & 0x2) != 0;
        while (position_ < bytes_.size() && bytes_[position_] != '\0') read_attribute();
        if (position_ >= bytes_.size()) refuse("the header has no end");
        ++position_;  // the empty name that ends the header; the chunk offset table follows
        if (!has_window_) return;  // tinyexr refuses a file without a data window
        const std::int64_t width = std::int64_t(window_[2]) - window_[0] + 1;
        const std::int64_t height = std::int64_t(window_[3]) - window_[1] + 1;
        check_image_size(width, height, path_);
        if (tiled_version && tile_width_ > 0)
            check_tiles(width, height);
        else
            check_scanlines(width, height);
    }

private:
    [[noreturn]] void refuse(const std::string& reason) const {
        throw InputError(path_, "not a valid OpenEXR file: " + reason);
    }

    std::int32_t int_at(std::size_t at) const {
        std::uint32_t value = 0;
        for (int i = 3; i >= 0; --i) value = (value << 8) | bytes_[at + static_cast<std::size_t>(i)];
        return static_cast<std::int32_t>(value);
    }

    std::string read_string(const char* what) {
        const auto begin = bytes_.begin() + static_cast<std::ptrdiff_t>(position_);
        const auto end = std::find(begin, bytes_.end(), '\0');
        if (end == bytes_.end()) refuse(std::string("the header ends inside an attribute ") + what);
        position_ += static_cast<std::size_t>(end - begin) + 1;
        return std::string(begin, end);
    }

    void read_attribute() {
        const std::string name = read_string("name");
        read_string("type");
        if (bytes_.size() - position_ < 4) refuse("the header ends inside attribute '" + name + "'");
        const auto size = static_cast<std::uint32_t>(int_at(position_));
        position_ += 4;
        if (bytes_.size() - position_ < size) refuse("attribute '" + name + "' runs past the end of the file");
        const std::size_t value = position_;
        position_ += size;
        if (name == "tiles") {
            // Tile width and height, then the level mode (low 4 bits) and rounding mode (bit 4).
            if (size != 9) refuse("the 'tiles' attribute has " + std::to_string(size) + " bytes, not 9");
            tile_width_ = int_at(value);
            tile_height_ = int_at(value + 4);
            if (tile_width_ < 1 || tile_height_ < 1 || tile_width_ > 65536 || tile_height_ > 65536)
                refuse("the tile size " + std::to_string(tile_width_) + "x" + std::to_string(tile_height_) +
                       " is not between 1x1 and 65536x65536");
            level_mode_ = bytes_[value + 8] & 0x0f;
            round_up_ = ((bytes_[value + 8] >> 4) & 1) != 0;
            if (level_mode_ > 2) refuse("the tile level mode is unknown");
        } else if (name == "channels") {
            check_channels(value, value + size);
        } else if (name == "dataWindow" && size >= 16) {
            for (int i = 0; i < 4; ++i) window_[i] = int_at(value + 4 * static_cast<std::size_t>(i));
            has_window_ = true;
        } else if (name == "compression" && size >= 1) {
            compression_ = bytes_[value];
        } else if (name == "chunkCount" && size >= 4) {
            chunk_count_ = int_at(value);
        }
    }

    // Each channel: its name (then \0), pixel type, linear flag and three reserved bytes, x and
    // y sampling; an empty name ends the list.
    void check_channels(std::size_t at, std::size_t end) {
        pixel_bytes_ = 0;
        while (at < end && bytes_[at] != '\0') {
            const auto name_end = std::find(bytes_.begin() + static_cast<std::ptrdiff_t>(at),
                                            bytes_.begin() + static_cast<std::ptrdiff_t>(end), '\0');
            const std::string channel(bytes_.begin() + static_cast<std::ptrdiff_t>(at), name_end);
            at += channel.size() + 1;
            if (name_end == bytes_.begin() + static_cast<std::ptrdiff_t>(end) || end - at < 16)
                refuse("the channel list is cut short");
            const std::int32_t pixel_type = int_at(at);
            if (pixel_type < TINYEXR_PIXELTYPE_UINT || pixel_type > TINYEXR_PIXELTYPE_FLOAT)
                refuse("channel '" + channel + "' has the unknown pixel type " + std::to_string(pixel_type));
            if (int_at(at + 8) != 1 || int_at(at + 12) != 1)
                refuse("channel '" + channel + "' is subsampled, which is not supported");
            pixel_bytes_ += pixel_type == TINYEXR_PIXELTYPE_HALF ? 2 : 4;
            at += 16;
        }
        if (at >= end) refuse("the channel list has no end");
    }

    // The offset table entry at `entry`, checked to point at a chunk with a header of
    // `header_bytes` (coordinates, then the data size) and its data inside the file; returns the
    // chunk's offset. Without compression, the data must hold `raw_bytes`: tinyexr reads a
    // 4-byte value up to 3 bytes past a shorter one.
    std::size_t chunk_at(std::size_t entry, std::size_t table_end, std::size_t header_bytes, std::int64_t raw_bytes) const {
        std::uint64_t offset = 0;
        for (int i = 7; i >= 0; --i) offset = (offset << 8) | bytes_[entry + static_cast<std::size_t>(i)];
        if (offset < table_end || offset > bytes_.size() || bytes_.size() - offset < header_bytes)
            refuse("a chunk offset points outside the file");
        const std::int32_t data_size = int_at(static_cast<std::size_t>(offset) + header_bytes - 4);
        if (data_size < 0 || std::uint64_t(data_size) > bytes_.size() - offset - header_bytes)
            refuse("a chunk runs past the end of the file");
        if (compression_ == 0 && data_size < raw_bytes) refuse("an uncompressed chunk is too short");
        // tinyexr takes a PIZ chunk as compressed unless its size is exactly the raw size.
        if (compression_ == 4 && data_size != raw_bytes)
            check_piz_header(static_cast<std::size_t>(offset) + header_bytes, data_size);
        return static_cast<std::size_t>(offset);
    }

    // PIZ data opens with the first and last index of the non-zero bytes of a bitmap (2 bytes
    // each), those bitmap bytes, then the 4-byte length of the Huffman data. tinyexr copies all of
    // them without comparing them with the chunk's size (found by fuzz_image: a heap read past
    // the end of the file in DecompressPiz), so they must fit in the chunk.
    void check_piz_header(std::size_t data, std::int32_t data_size) const {
        if (data_size < 4) refuse("a PIZ chunk is too short for its header");
        const unsigned first = bytes_[data] | (unsigned(bytes_[data + 1]) << 8);
        const unsigned last = bytes_[data + 2] | (unsigned(bytes_[data + 3]) << 8);
        const std::int64_t needed = 4 + (first <= last ? std::int64_t(last) - first + 1 : 0) + 4;
        if (data_size < needed) refuse("a PIZ chunk's bitmap and Huffman length run past the end of the chunk");
    }

    // Scanline files: blocks of 1, 16 (ZIP) or 32 (PIZ) rows, each chunk starting with its first
    // row's y coordinate (tinyexr sizes its offset table from chunkCount when it is given).
    void check_scanlines(std::int64_t width, std::int64_t height) const {
        const std::int64_t lines = compression_ == 3 ? 16 : compression_ == 4 ? 32 : 1;
        const std::int64_t blocks = (height + lines - 1) / lines;
        if (chunk_count_.has_value() && *chunk_count_ != blocks) refuse("the chunkCount attribute does not match the image");
        if (blocks > std::int64_t(bytes_.size() / 8)) refuse("the file is too short for its " + std::to_string(blocks) + " blocks of rows");
        const std::size_t table_end = position_ + 8 * static_cast<std::size_t>(blocks);
        if (table_end > bytes_.size()) refuse("the offset table runs past the end of the file");
        for (std::int64_t block = 0; block < blocks; ++block) {
            const std::int64_t rows = std::min(lines, height - block * lines);
            const std::size_t chunk = chunk_at(position_ + 8 * static_cast<std::size_t>(block), table_end, 8,
                                               rows * width * pixel_bytes_);
            if (int_at(chunk) != window_[1] + block * lines) refuse("a block of rows is not where its offset table entry says");
        }
    }

    // The number of levels along a size (OpenEXR's roundLog2 + 1) and a level's size.
    std::int64_t level_count(std::int64_t size) const {
        std::int64_t log = 0;
        while ((std::int64_t(1) << (log + 1)) <= size) ++log;              // floor(log2(size))
        if (round_up_ && (std::int64_t(1) << log) < size) ++log;           // ceil
        return log + 1;
    }
    std::int64_t level_size(std::int64_t size, std::int64_t level) const {
        const std::int64_t divided = round_up_ ? (size + (std::int64_t(1) << level) - 1) >> level : size >> level;
        return std::max<std::int64_t>(divided, 1);
    }

    // Every entry of the offset table must point at a chunk inside the file whose tile and level
    // coordinates are the ones that table position stands for (tinyexr's order: levels, then
    // rows of tiles).
    void check_tiles(std::int64_t width, std::int64_t height) {
        std::vector<std::array<std::int64_t, 4>> levels;  // level x, level y, tiles across, tiles down
        const std::int64_t x_levels = level_mode_ == 0 ? 1 : level_count(level_mode_ == 1 ? std::max(width, height) : width);
        const std::int64_t y_levels = level_mode_ == 0 ? 1 : level_mode_ == 1 ? x_levels : level_count(height);
        for (std::int64_t ly = 0; ly < y_levels; ++ly)
            for (std::int64_t lx = 0; lx < x_levels; ++lx) {
                if (level_mode_ != 2 && lx != ly) continue;  // a mipmap has the diagonal only
                const std::int64_t across = (level_size(width, lx) + tile_width_ - 1) / tile_width_;
                const std::int64_t down = (level_size(height, ly) + tile_height_ - 1) / tile_height_;
                levels.push_back({lx, ly, across, down});
            }
        std::int64_t chunks = 0;
        for (const auto& level : levels) chunks += level[2] * level[3];
        if (chunk_count_.has_value() && *chunk_count_ != chunks) refuse("the chunkCount attribute does not match the tiles");
        if (chunks > std::int64_t(bytes_.size() / 8)) refuse("the file is too short for its " + std::to_string(chunks) + " tiles");
        const std::size_t table_end = position_ + 8 * static_cast<std::size_t>(chunks);
        if (table_end > bytes_.size()) refuse("the tile offset table runs past the end of the file");
        std::size_t entry = position_;
        for (const auto& [lx, ly, across, down] : levels)
            for (std::int64_t y = 0; y < down; ++y)
                for (std::int64_t x = 0; x < across; ++x, entry += 8) {
                    const std::int64_t tile_width = std::min<std::int64_t>(tile_width_, level_size(width, lx) - x * tile_width_);
                    const std::int64_t tile_height = std::min<std::int64_t>(tile_height_, level_size(height, ly) - y * tile_height_);
                    const std::size_t offset = chunk_at(entry, table_end, 20, tile_width * tile_height * pixel_bytes_);
                    if (int_at(offset) != x || int_at(offset + 4) != y || int_at(offset + 8) != lx || int_at(offset + 12) != ly)
                        refuse("a tile chunk is not the tile its offset table entry stands for");
                }
    }

    const Bytes& bytes_;
    const std::string& path_;
    std::size_t position_ = 8;  // after the magic number and the version field
    std::int32_t tile_width_ = 0, tile_height_ = 0;
    int level_mode_ = 0;
    bool round_up_ = false;
    std::int32_t window_[4] = {0, 0, 0, 0};
    bool has_window_ = false;
    int compression_ = 0;
    std::int64_t pixel_bytes_ = 0;  // the size of one pixel of every channel, uncompressed
    std::optional<std::int32_t> chunk_count_;
};

}  // namespace freezeray::image_io
