// Writing and reading FRRAYS01 ray batches, with every record checked on the way in.
#include "ray_batch.hpp"

#include "binary_file.hpp"

#include "freezeray/error.hpp"

#include <cmath>
#include <limits>

namespace freezeray::benchmark {

namespace {

constexpr char Magic[] = "FRRAYS01";
constexpr std::size_t MagicBytes = 8;

std::string record_place(const std::string& path, std::uint64_t record) {
    return path + ": record " + std::to_string(record) + " (byte " +
           std::to_string(RayFileHeaderBytes + record * RayRecordBytes) + ")";
}

bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string describe(const Vec3& v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

// Throws unless the ray is one the accelerators can be asked about.
void check_ray(const Ray& ray, const std::string& place) {
    if (!is_finite(ray.origin)) throw InputError(place, "the origin " + describe(ray.origin) + " is not finite");
    if (!is_finite(ray.direction))
        throw InputError(place, "the direction " + describe(ray.direction) + " is not finite");
    const float length = glm::length(ray.direction);
    if (!(std::abs(length - 1.0f) <= 1e-3f))
        throw InputError(place, "the direction " + describe(ray.direction) + " has length " + std::to_string(length) +
                                    ", not 1");
    if (!(ray.tmax > 0.0f)) throw InputError(place, "tmax is " + std::to_string(ray.tmax) + "; it must be positive");
}

}  // namespace

const char* ray_kind_name(RayKind kind) {
    switch (kind) {
        case RayKind::Primary: return "primary";
        case RayKind::Diffuse: return "diffuse";
        case RayKind::Shadow: return "shadow";
    }
    return "unknown";
}

void RayBatches::keep_first(std::size_t count) {
    for (std::vector<Ray>& batch : rays)
        if (batch.size() > count) batch.resize(count);
}

void write_ray_batches(const std::string& path, const RayBatches& batches) {
    LittleEndianWriter out;
    out.bytes(Magic, MagicBytes);
    for (RayKind kind : all_ray_kinds) {
        if (batches.of(kind).size() > std::numeric_limits<std::uint32_t>::max())
            throw InputError(path, std::string("too many ") + ray_kind_name(kind) + " rays for FRRAYS01's 32-bit count");
        out.u32(static_cast<std::uint32_t>(batches.of(kind).size()));
    }
    for (RayKind kind : all_ray_kinds) {
        for (const Ray& ray : batches.of(kind)) {
            for (int i = 0; i < 3; ++i) out.f32(ray.origin[i]);
            for (int i = 0; i < 3; ++i) out.f32(ray.direction[i]);
            out.f32(ray.tmax);
            out.u8(static_cast<std::uint8_t>(kind));
        }
    }
    write_binary_file_atomically(path, out.buffer());
}

RayBatches read_ray_batches(const std::string& path) {
    const Bytes bytes = read_binary_file(path);
    if (bytes.size() < RayFileHeaderBytes)
        throw InputError(path, "truncated: " + std::to_string(bytes.size()) + " bytes, shorter than the " +
                                   std::to_string(RayFileHeaderBytes) + "-byte FRRAYS01 header");
    LittleEndianReader in(bytes);
    if (in.text(MagicBytes) != std::string(Magic, MagicBytes))
        throw InputError(path, "not an FRRAYS01 ray file (its first 8 bytes are not \"FRRAYS01\")");

    std::array<std::uint64_t, 3> counts{};
    for (std::uint64_t& count : counts) count = in.u32();
    const std::uint64_t records = counts[0] + counts[1] + counts[2];
    const std::uint64_t expected_bytes = RayFileHeaderBytes + records * RayRecordBytes;
    if (bytes.size() != expected_bytes) {
        const std::string counts_text = std::to_string(counts[0]) + " primary + " + std::to_string(counts[1]) +
                                        " diffuse + " + std::to_string(counts[2]) + " shadow";
        const std::uint64_t whole_records = (bytes.size() - RayFileHeaderBytes) / RayRecordBytes;
        throw InputError(path, "the header declares " + counts_text + " = " + std::to_string(records) +
                                   " records (" + std::to_string(expected_bytes) + " bytes), but the file has " +
                                   std::to_string(bytes.size()) + " bytes" +
                                   (bytes.size() < expected_bytes
                                        ? ": truncated at record " + std::to_string(whole_records)
                                        : ": data after the last record"));
    }

    RayBatches batches;
    std::uint64_t record = 0;
    for (RayKind kind : all_ray_kinds) {
        std::vector<Ray>& batch = batches.of(kind);
        batch.reserve(counts[static_cast<std::size_t>(kind)]);
        for (std::uint64_t i = 0; i < counts[static_cast<std::size_t>(kind)]; ++i, ++record) {
            Ray ray;
            for (int axis = 0; axis < 3; ++axis) ray.origin[axis] = in.f32();
            for (int axis = 0; axis < 3; ++axis) ray.direction[axis] = in.f32();
            ray.tmax = in.f32();
            const std::uint8_t tag = in.u8();
            if (tag > 2)
                throw InputError(record_place(path, record),
                                 "tag " + std::to_string(tag) + " is none of 0 (primary), 1 (diffuse), 2 (shadow)");
            if (tag != static_cast<std::uint8_t>(kind))
                throw InputError(record_place(path, record),
                                 "tag " + std::to_string(tag) + " (" + ray_kind_name(static_cast<RayKind>(tag)) +
                                     ") where the header's counts put a " + ray_kind_name(kind) + " ray");
            check_ray(ray, record_place(path, record));
            batch.push_back(ray);
        }
    }
    return batches;
}

}  // namespace freezeray::benchmark
