// Helpers for the image file tests: a temporary folder, raw file contents, and the message of
// an expected InputError.
#pragma once

#include "freezeray/error.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

namespace freezeray::test {

// A fresh, empty folder under the system's temporary folder, removed with its content when the
// test ends (whether it passes or not).
class TemporaryFolder {
public:
    TemporaryFolder() {
        static std::atomic<int> counter{0};
        path_ = std::filesystem::temp_directory_path() /
                ("freezeray-tests-images-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TemporaryFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;

    // The path of `name` inside the folder.
    std::string file(const std::string& name) const { return (path_ / name).string(); }

    // The names of everything in the folder, sorted.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(path_)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    std::filesystem::path path_;
};

// The message of the InputError that `action` throws; fails the test if it throws none.
template <typename Action>
std::string input_error_message(Action action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    FAIL("expected an InputError, but nothing was thrown");
    return {};
}

// The four bytes of a float in little-endian order.
inline std::vector<unsigned char> little_endian_bytes(float value) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    return {static_cast<unsigned char>(bits), static_cast<unsigned char>(bits >> 8),
            static_cast<unsigned char>(bits >> 16), static_cast<unsigned char>(bits >> 24)};
}

// The whole content of a file.
inline std::vector<unsigned char> read_bytes(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// Writes raw bytes to a file.
inline void write_bytes(const std::string& path, const std::vector<unsigned char>& bytes) {
    std::ofstream file(path, std::ios::binary);
    file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    REQUIRE(file.good());
}

// Writes `text`, then `values` as 32-bit floats in the given byte order (to build PFM files).
inline void write_file(const std::string& path, const std::string& text, const std::vector<float>& values = {},
                       bool little_endian = true) {
    std::vector<unsigned char> bytes(text.begin(), text.end());
    for (float value : values) {
        std::vector<unsigned char> four = little_endian_bytes(value);
        if (!little_endian) std::reverse(four.begin(), four.end());
        bytes.insert(bytes.end(), four.begin(), four.end());
    }
    write_bytes(path, bytes);
}

// The offset of the value of the EXR header attribute `name` of type `type` (after its 4-byte
// size) in `bytes`; fails the test if there is none.
inline std::size_t exr_attribute_value(const std::vector<unsigned char>& bytes, const std::string& name, const std::string& type) {
    const std::string key = name + '\0' + type + '\0';
    const auto found = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
    REQUIRE(found != bytes.end());
    return static_cast<std::size_t>(found - bytes.begin()) + key.size() + 4;
}

// The offset just past the header of a single-part EXR file in `bytes`, where its table of chunk
// offsets begins: the header is attributes (name\0 type\0 4-byte size, value) ended by an
// empty name (https://openexr.com/en/latest/OpenEXRFileLayout.html).
inline std::size_t exr_header_end(const std::vector<unsigned char>& bytes) {
    std::size_t at = 8;  // magic number, version field
    while (bytes.at(at) != 0) {
        while (bytes.at(at++) != 0) {}  // name
        while (bytes.at(at++) != 0) {}  // type
        std::uint32_t size = 0;
        for (int i = 3; i >= 0; --i) size = (size << 8) | bytes.at(at + static_cast<std::size_t>(i));
        at += 4 + size;
    }
    return at + 1;
}

// Overwrites a little-endian 32-bit number in a byte vector.
inline void put_little_endian(std::vector<unsigned char>& bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<unsigned char>(value >> (8 * i));
}

}  // namespace freezeray::test
