// Little-endian binary files, read whole and written atomically: what the ray-batch (FRRAYS01)
// and hit (FRHITS01) formats of the ray benchmark share.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace freezeray::benchmark {

using Bytes = std::vector<unsigned char>;

// Appends values to a byte buffer in little-endian order, whatever the machine's own order.
class LittleEndianWriter {
public:
    void bytes(const void* data, std::size_t count);
    void u8(std::uint8_t value);
    void u32(std::uint32_t value);
    void i32(std::int32_t value);
    void f32(float value);  // IEEE 754 binary32, bit for bit (NaN payloads and -0 kept)

    const Bytes& buffer() const { return buffer_; }

private:
    Bytes buffer_;
};

// Reads little-endian values from a byte buffer. The caller checks the size first (the formats
// know how long they must be); reading past the end throws std::out_of_range, a bug, not input.
class LittleEndianReader {
public:
    explicit LittleEndianReader(const Bytes& buffer) : buffer_(buffer) {}

    std::uint8_t u8();
    std::uint32_t u32();
    std::int32_t i32();
    float f32();
    std::string text(std::size_t count);

    std::size_t position() const { return position_; }

private:
    const unsigned char* take(std::size_t count);

    const Bytes& buffer_;
    std::size_t position_ = 0;
};

// The whole file. Throws InputError(path, ...) when it does not exist or cannot be read.
Bytes read_binary_file(const std::string& path);

// Writes the bytes to `path` atomically: to a temporary file beside it, then renamed over it
// (POSIX rename replaces the destination in one step), so that a reader sees the old file or the
// new one, never a torn one, and a failed write leaves nothing behind. Throws InputError.
void write_binary_file_atomically(const std::string& path, const Bytes& bytes);

// Throws InputError(path, ...) unless the folder that would hold `path` exists and `path` is not
// itself a folder: checked before a long measurement, so that its result is not lost at the end.
void check_output_path(const std::string& path);

}  // namespace freezeray::benchmark
