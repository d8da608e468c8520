// OpenEXR input and output streams over bytes in memory, so that image_io_exr.cpp decodes and
// encodes in memory like the other formats and image_io.cpp alone deals with files (reading,
// atomic writing). The interface is OpenEXR's Imf::IStream and Imf::OStream (ImfIO.h).
// Private to image_io_exr.cpp.
#pragma once

#include "image_io_formats.hpp"

#include <Iex.h>
#include <ImfIO.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace freezeray::image_io {

// Reads from a byte vector that outlives the stream. Asking for bytes past the end throws
// Iex::InputExc, as ImfIO.h requires of read(); OpenEXR turns that into its own errors.
class MemoryInputStream : public Imf::IStream {
public:
    MemoryInputStream(const Bytes& bytes, const std::string& path) : Imf::IStream(path.c_str()), bytes_(bytes) {}

    // Copies the next n bytes to c; returns false once the last byte of the file has been read.
    bool read(char c[], int n) override {
        if (n < 0 || position_ > bytes_.size() || bytes_.size() - position_ < static_cast<std::uint64_t>(n)) {
            throw Iex::InputExc("unexpected end of the file");
        }
        if (n == 0) return position_ < bytes_.size();
        std::memcpy(c, bytes_.data() + position_, static_cast<std::size_t>(n));
        position_ += static_cast<std::uint64_t>(n);
        return position_ < bytes_.size();
    }
    std::uint64_t tellg() override { return position_; }
    // Any position may be set; reading past the end is what fails.
    void seekg(std::uint64_t position) override { position_ = position; }

private:
    const Bytes& bytes_;
    std::uint64_t position_ = 0;
};

// Writes into a byte vector, growing it as needed. OpenEXR seeks back to fill in the table of
// chunk offsets once the pixels are written, so a write may land before the end.
class MemoryOutputStream : public Imf::OStream {
public:
    explicit MemoryOutputStream(const std::string& path) : Imf::OStream(path.c_str()) {}

    void write(const char c[], int n) override {
        if (n < 0) throw Iex::ArgExc("negative write size");
        if (n == 0) return;
        const std::size_t end = static_cast<std::size_t>(position_) + static_cast<std::size_t>(n);
        if (end > bytes_.size()) bytes_.resize(end);
        std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
        position_ = end;
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = position; }

    // The file written so far.
    Bytes& bytes() { return bytes_; }

private:
    Bytes bytes_;
    std::uint64_t position_ = 0;
};

}  // namespace freezeray::image_io
