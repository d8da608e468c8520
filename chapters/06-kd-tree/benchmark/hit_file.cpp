// Writing and reading FRHITS01 hit files.
#include "hit_file.hpp"

#include "binary_file.hpp"

#include "freezeray/error.hpp"

#include <cmath>

namespace freezeray::benchmark {

namespace {

constexpr char Magic[] = "FRHITS01";
constexpr std::size_t MagicBytes = 8;

void check_hit(const ClosestHit& hit, std::uint32_t triangle_count, const std::string& place) {
    if (hit.triangle < -1 || (hit.triangle >= 0 && static_cast<std::uint32_t>(hit.triangle) >= triangle_count))
        throw InputError(place, "triangle " + std::to_string(hit.triangle) + " is neither -1 (a miss) nor below the " +
                                    std::to_string(triangle_count) + " triangles of the header");
    if (hit.is_miss() && !(std::isinf(hit.t) && hit.t > 0.0f))
        throw InputError(place, "a miss has t " + std::to_string(hit.t) + ", not +inf");
    if (!hit.is_miss() && !(std::isfinite(hit.t) && hit.t > 0.0f))
        throw InputError(place, "a hit has t " + std::to_string(hit.t) + ", not a finite positive distance");
}

}  // namespace

void write_hit_file(const std::string& path, const HitFile& hits) {
    LittleEndianWriter out;
    out.bytes(Magic, MagicBytes);
    out.u32(static_cast<std::uint32_t>(hits.primary.size()));
    out.u32(static_cast<std::uint32_t>(hits.diffuse.size()));
    out.u32(hits.triangle_count);
    for (const std::vector<ClosestHit>* batch : {&hits.primary, &hits.diffuse}) {
        for (const ClosestHit& hit : *batch) {
            out.i32(hit.triangle);
            out.f32(hit.t);
        }
    }
    write_binary_file_atomically(path, out.buffer());
}

HitFile read_hit_file(const std::string& path) {
    const Bytes bytes = read_binary_file(path);
    if (bytes.size() < HitFileHeaderBytes)
        throw InputError(path, "truncated: " + std::to_string(bytes.size()) + " bytes, shorter than the " +
                                   std::to_string(HitFileHeaderBytes) + "-byte FRHITS01 header");
    LittleEndianReader in(bytes);
    if (in.text(MagicBytes) != std::string(Magic, MagicBytes))
        throw InputError(path, "not an FRHITS01 hit file (its first 8 bytes are not \"FRHITS01\")");
    const std::uint64_t primary_count = in.u32();
    const std::uint64_t diffuse_count = in.u32();
    HitFile hits;
    hits.triangle_count = in.u32();
    const std::uint64_t expected_bytes = HitFileHeaderBytes + (primary_count + diffuse_count) * HitRecordBytes;
    if (bytes.size() != expected_bytes)
        throw InputError(path, "the header declares " + std::to_string(primary_count) + " primary + " +
                                   std::to_string(diffuse_count) + " diffuse records (" +
                                   std::to_string(expected_bytes) + " bytes), but the file has " +
                                   std::to_string(bytes.size()) + " bytes");

    std::uint64_t record = 0;
    for (auto [batch, count] : {std::pair{&hits.primary, primary_count}, std::pair{&hits.diffuse, diffuse_count}}) {
        batch->reserve(count);
        for (std::uint64_t i = 0; i < count; ++i, ++record) {
            ClosestHit hit;
            hit.triangle = in.i32();
            hit.t = in.f32();
            check_hit(hit, hits.triangle_count,
                      path + ": record " + std::to_string(record) + " (byte " +
                          std::to_string(HitFileHeaderBytes + record * HitRecordBytes) + ")");
            batch->push_back(hit);
        }
    }
    return hits;
}

}  // namespace freezeray::benchmark
