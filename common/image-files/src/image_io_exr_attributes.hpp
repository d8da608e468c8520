// A walk over the attributes of an OpenEXR header before OpenEXR reads it (see
// check_exr_attributes). Private to image_io_exr.cpp.
#pragma once

#include "freezeray/error.hpp"
#include "image_io_formats.hpp"

#include <ImfVersion.h>

#include <cstdint>
#include <map>
#include <string>

namespace freezeray::image_io {

namespace exr_attributes {

[[noreturn]] inline void refuse(const std::string& path, const std::string& reason) {
    throw InputError(path, "not a valid OpenEXR file: " + reason);
}

// The little-endian 32-bit integer at `at` (the caller checks that its 4 bytes exist).
inline std::int32_t int_at(const Bytes& bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = (value << 8) | bytes[at + static_cast<std::size_t>(i)];
    return static_cast<std::int32_t>(value);
}

// The null-terminated name at `at` (an attribute's name or type, or a channel's name, as `what`
// says), which must end before `end` (else refused as `where` ending inside it); moves `at` past
// its terminator. OpenEXR reads at most 255 characters and a terminator (ImfName.h,
// Name::MAX_LENGTH).
inline std::string read_name(const Bytes& bytes, std::size_t& at, std::size_t end, const std::string& what,
                             const std::string& where, const std::string& path) {
    std::string name;
    while (at < end && bytes[at] != '\0') {
        if (name.size() == 255) refuse(path, what + " is longer than 255 characters");
        name += static_cast<char>(bytes[at++]);
    }
    if (at >= end) refuse(path, where + " ends inside " + what);
    ++at;  // the terminator
    return name;
}

// The number of bytes OpenEXR's reader takes for an attribute of a fixed-size type whatever size
// the file declares (each TypedAttribute<T>::readValueFrom of OpenEXR 3.1; the sizes are those of
// the file layout document, https://openexr.com/en/latest/OpenEXRFileLayout.html), or 0 for
// the types whose size the file gives.
inline int fixed_size_of(const std::string& type) {
    static const std::map<std::string, int> sizes = {
        {"box2i", 16},   {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
        {"double", 8},   {"envmap", 1}, {"float", 4},           {"int", 4},         {"keycode", 28},
        {"lineOrder", 1}, {"m33d", 72}, {"m33f", 36},           {"m44d", 128},      {"m44f", 64},
        {"rational", 8}, {"tiledesc", 9}, {"timecode", 8},      {"v2d", 16},        {"v2f", 8},
        {"v2i", 8},      {"v3d", 24},   {"v3f", 12},            {"v3i", 12}};
    const auto found = sizes.find(type);
    return found == sizes.end() ? 0 : found->second;
}

// A channel list ("chlist"): per channel a name, then 16 bytes (pixel type, linear flag and
// three reserved bytes, x and y sampling); an empty name ends the list. OpenEXR reads until that
// empty name, so it must be the last byte of the attribute.
inline void check_channel_list(const Bytes& bytes, std::size_t at, std::size_t end, const std::string& path) {
    while (true) {
        const std::string channel = read_name(bytes, at, end, "a channel name", "the channel list", path);
        if (channel.empty()) break;
        if (end - at < 16) refuse(path, "the channel list is cut short after channel '" + channel + "'");
        at += 16;
    }
    if (at != end) refuse(path, "the channel list ends before its attribute does");
}

}  // namespace exr_attributes

// Checks that the bytes are a single-part, non-deep OpenEXR file whose header attributes each lie
// inside the file, and returns the version field. OpenEXR 3.1's C++ reader trusts the size an
// attribute declares and allocates it before reading (a string is resized to it,
// ImfStringAttribute.cpp; an unknown type is copied into a buffer of that size,
// ImfOpaqueAttribute.cpp), so a 100-byte file could make it allocate 2 GB. And since it reads a
// fixed-size type at its fixed size whatever the file declares, the walk also requires those
// sizes, or the reader would take the next attribute's size from other bytes than we checked.
// Header layout: magic number, version field, then attributes (name\0 type\0 size value) ended
// by an empty name (https://openexr.com/en/latest/OpenEXRFileLayout.html).
inline int check_exr_attributes(const Bytes& bytes, const std::string& path) {
    using namespace exr_attributes;
    if (bytes.size() < 8 || !Imf::isImfMagic(reinterpret_cast<const char*>(bytes.data())) ||
        Imf::getVersion(int_at(bytes, 4)) != Imf::EXR_VERSION) {
        throw InputError(path, "not an OpenEXR file (bad magic number or version)");
    }
    const int version = int_at(bytes, 4);
    if (Imf::isMultiPart(version) || Imf::isNonImage(version)) {
        throw InputError(path, "multi-part and deep OpenEXR files are not supported");
    }
    std::size_t at = 8;
    while (true) {
        const std::string name = read_name(bytes, at, bytes.size(), "an attribute name", "the header", path);
        if (name.empty()) return version;
        const std::string type = read_name(bytes, at, bytes.size(), "an attribute type", "the header", path);
        if (bytes.size() - at < 4) refuse(path, "the header ends inside attribute '" + name + "'");
        const std::int32_t size = int_at(bytes, at);
        at += 4;
        if (size < 0 || static_cast<std::uint64_t>(size) > bytes.size() - at) {
            refuse(path, "attribute '" + name + "' runs past the end of the file");
        }
        const int fixed_size = fixed_size_of(type);
        if (fixed_size > 0 && size != fixed_size) {
            refuse(path, "attribute '" + name + "' of type " + type + " has " + std::to_string(size) + " bytes, not " +
                             std::to_string(fixed_size));
        }
        if (type == "chlist") check_channel_list(bytes, at, at + static_cast<std::size_t>(size), path);
        // OpenEXR reads size / 4 floats of a float vector, so the size must be a multiple of 4.
        if (type == "floatvector" && size % 4 != 0) {
            refuse(path, "attribute '" + name + "' holds a fraction of a float");
        }
        // OpenEXR 3.1's reader of ID manifests takes 4 bytes more than the attribute declares
        // (ImfIDManifestAttribute.cpp: an 8-byte length, then size - 4 bytes), so it would read the
        // next attribute from the wrong place.
        if (type == "idmanifest") {
            throw InputError(path, "OpenEXR ID manifests (attribute '" + name + "') are not supported");
        }
        at += static_cast<std::size_t>(size);
    }
}

}  // namespace freezeray::image_io
