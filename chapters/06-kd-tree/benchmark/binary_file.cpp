// Little-endian encoding by shifts (independent of the machine's byte order), whole-file reads,
// atomic writes.
#include "binary_file.hpp"

#include "freezeray/error.hpp"

#include <atomic>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <unistd.h>  // getpid, to name temporary files

namespace freezeray::benchmark {

namespace fs = std::filesystem;

void LittleEndianWriter::bytes(const void* data, std::size_t count) {
    const auto* first = static_cast<const unsigned char*>(data);
    buffer_.insert(buffer_.end(), first, first + count);
}

void LittleEndianWriter::u8(std::uint8_t value) { buffer_.push_back(value); }

void LittleEndianWriter::u32(std::uint32_t value) {
    for (int byte = 0; byte < 4; ++byte) buffer_.push_back(static_cast<unsigned char>(value >> (8 * byte)));
}

void LittleEndianWriter::i32(std::int32_t value) { u32(static_cast<std::uint32_t>(value)); }

void LittleEndianWriter::f32(float value) { u32(std::bit_cast<std::uint32_t>(value)); }

const unsigned char* LittleEndianReader::take(std::size_t count) {
    if (count > buffer_.size() - position_) throw std::out_of_range("LittleEndianReader: read past the end");
    const unsigned char* first = buffer_.data() + position_;
    position_ += count;
    return first;
}

std::uint8_t LittleEndianReader::u8() { return *take(1); }

std::uint32_t LittleEndianReader::u32() {
    const unsigned char* b = take(4);
    return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
           static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}

std::int32_t LittleEndianReader::i32() { return static_cast<std::int32_t>(u32()); }

float LittleEndianReader::f32() { return std::bit_cast<float>(u32()); }

std::string LittleEndianReader::text(std::size_t count) {
    const unsigned char* first = take(count);
    return std::string(reinterpret_cast<const char*>(first), count);
}

Bytes read_binary_file(const std::string& path) {
    std::error_code error;
    if (!fs::is_regular_file(path, error)) throw InputError(path, "the file does not exist (or is not a regular file)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "the file cannot be opened: " + std::string(std::strerror(errno)));
    const std::uintmax_t size = fs::file_size(path, error);
    if (error) throw InputError(path, "the file's size cannot be read: " + error.message());
    Bytes bytes(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) throw InputError(path, "the file cannot be read to its end");
    return bytes;
}

void check_output_path(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    const fs::path folder = parent.empty() ? fs::path(".") : parent;
    std::error_code error;
    if (!fs::is_directory(folder, error)) throw InputError(path, "the folder '" + folder.string() + "' does not exist");
    if (fs::is_directory(path, error)) throw InputError(path, "is a folder, not a file");
}

void write_binary_file_atomically(const std::string& path, const Bytes& bytes) {
    check_output_path(path);
    std::error_code error;

    // Unique per process and per call, so that two writers never share a temporary file.
    static std::atomic<unsigned> counter{0};
    const std::string temporary = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (file == nullptr) throw InputError(path, "cannot create '" + temporary + "': " + std::strerror(errno));
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size() && std::fflush(file) == 0;
    const std::string write_error = written ? std::string() : std::strerror(errno);
    const bool closed = std::fclose(file) == 0;
    if (!written || !closed) {
        fs::remove(temporary, error);
        throw InputError(path, "cannot write '" + temporary + "': " + (written ? std::strerror(errno) : write_error));
    }
    fs::rename(temporary, path, error);
    if (error) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw InputError(path, "cannot move the temporary file into place: " + error.message());
    }
}

}  // namespace freezeray::benchmark
