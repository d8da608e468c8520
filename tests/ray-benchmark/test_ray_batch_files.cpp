// The ray benchmark's file formats: FRRAYS01 ray batches and FRHITS01 hits
// (chapters/06-kd-tree/benchmark/ray_batch.cpp, hit_file.cpp). Round trips are bit-exact, and
// every kind of damaged file is refused with a message naming the file and the record.
#include "binary_file.hpp"
#include "hit_file.hpp"
#include "ray_batch.hpp"

#include "freezeray/error.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

using namespace freezeray;
using namespace freezeray::benchmark;
using Catch::Matchers::Contains;

namespace {

// Three small batches with awkward values: negative zero, denormals, huge and tiny numbers.
RayBatches sample_batches() {
    RayBatches batches;
    const float inf = std::numeric_limits<float>::infinity();
    batches.of(RayKind::Primary) = {Ray{Vec3(1.0f, -2.5f, 3.25f), glm::normalize(Vec3(0.3f, -0.4f, 0.866f)), inf},
                                    Ray{Vec3(-0.0f, 1e-40f, 3e38f), Vec3(0.0f, 0.0f, -1.0f), inf}};
    batches.of(RayKind::Diffuse) = {Ray{Vec3(0.1f, 0.2f, 0.3f), glm::normalize(Vec3(1.0f, 1.0f, 1.0f)), inf}};
    batches.of(RayKind::Shadow) = {Ray{Vec3(5.0f), Vec3(1.0f, 0.0f, 0.0f), 12.5f},
                                   Ray{Vec3(-5.0f), Vec3(0.0f, 1.0f, 0.0f), 1e-30f},
                                   Ray{Vec3(7.0f), glm::normalize(Vec3(-1.0f, 2.0f, -3.0f)), 0.75f}};
    return batches;
}

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

bool same_bits(const Ray& a, const Ray& b) {
    for (int i = 0; i < 3; ++i)
        if (!same_bits(a.origin[i], b.origin[i]) || !same_bits(a.direction[i], b.direction[i])) return false;
    return same_bits(a.tmax, b.tmax);
}

Bytes file_bytes(const std::string& path) { return read_binary_file(path); }

void write_raw(const std::string& path, const Bytes& bytes) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                 static_cast<std::streamsize>(bytes.size()));
}

// The byte offset of field `field` (0..6 the floats, 7 the tag) of record `record`.
std::size_t field_offset(std::size_t record, int field) {
    return RayFileHeaderBytes + record * RayRecordBytes + static_cast<std::size_t>(field) * 4;
}

void put_float(Bytes& bytes, std::size_t offset, float value) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    for (int i = 0; i < 4; ++i) bytes[offset + static_cast<std::size_t>(i)] = static_cast<unsigned char>(bits >> (8 * i));
}

// The message of the InputError that reading the file must throw.
std::string read_error(const std::string& path) {
    try {
        read_ray_batches(path);
    } catch (const InputError& error) {
        return error.what();
    }
    FAIL("reading " << path << " did not throw InputError");
    return {};
}

}  // namespace

TEST_CASE("FRRAYS01: a written batch reads back bit for bit", "[unit][ray-benchmark]") {
    testing::TemporaryFolder folder;
    const RayBatches written = sample_batches();
    write_ray_batches(folder.file("batches.rays"), written);
    const RayBatches read = read_ray_batches(folder.file("batches.rays"));
    for (RayKind kind : all_ray_kinds) {
        INFO(ray_kind_name(kind));
        REQUIRE(read.of(kind).size() == written.of(kind).size());
        for (std::size_t i = 0; i < written.of(kind).size(); ++i) CHECK(same_bits(read.of(kind)[i], written.of(kind)[i]));
    }
}

TEST_CASE("FRRAYS01: the layout is the documented one (little-endian, packed, 29-byte records)",
          "[unit][ray-benchmark]") {
    testing::TemporaryFolder folder;
    write_ray_batches(folder.file("batches.rays"), sample_batches());
    const Bytes bytes = file_bytes(folder.file("batches.rays"));
    REQUIRE(bytes.size() == 8 + 12 + 6 * 29);
    CHECK(std::string(bytes.begin(), bytes.begin() + 8) == "FRRAYS01");
    CHECK(bytes[8] == 2);   // Na, lowest byte first
    CHECK(bytes[12] == 1);  // Nb
    CHECK(bytes[16] == 3);  // Nc
    // Record 0: ox = 1.0f = 0x3f800000, stored 00 00 80 3f; its tag, byte 28 of the record, is 0.
    CHECK(bytes[20] == 0x00);
    CHECK(bytes[22] == 0x80);
    CHECK(bytes[23] == 0x3f);
    CHECK(bytes[20 + 28] == 0);
    CHECK(bytes[20 + 2 * 29 + 28] == 1);  // record 2 is the diffuse ray
    CHECK(bytes[20 + 5 * 29 + 28] == 2);  // record 5 the last shadow ray
}

TEST_CASE("FRRAYS01: keep_first keeps the first rays of each kind", "[unit][ray-benchmark]") {
    RayBatches batches = sample_batches();
    batches.keep_first(1);
    CHECK(batches.of(RayKind::Primary).size() == 1);
    CHECK(batches.of(RayKind::Diffuse).size() == 1);
    REQUIRE(batches.of(RayKind::Shadow).size() == 1);
    CHECK(batches.of(RayKind::Shadow)[0].tmax == 12.5f);
}

TEST_CASE("FRRAYS01: damaged files are refused, naming the file and the record", "[unit][ray-benchmark]") {
    testing::TemporaryFolder folder;
    const std::string good = folder.file("good.rays");
    write_ray_batches(good, sample_batches());
    const Bytes bytes = file_bytes(good);
    const std::string bad = folder.file("bad.rays");

    SECTION("a missing file") { CHECK_THAT(read_error(folder.file("missing.rays")), Contains("missing.rays")); }
    SECTION("shorter than the header") {
        write_raw(bad, Bytes(bytes.begin(), bytes.begin() + 11));
        CHECK_THAT(read_error(bad), Contains("bad.rays") && Contains("truncated") && Contains("header"));
    }
    SECTION("truncated in the middle of a record") {
        write_raw(bad, Bytes(bytes.begin(), bytes.end() - 10));
        CHECK_THAT(read_error(bad), Contains("bad.rays") && Contains("truncated at record 5"));
    }
    SECTION("a wrong magic") {
        Bytes changed = bytes;
        changed[7] = '2';
        write_raw(bad, changed);
        CHECK_THAT(read_error(bad), Contains("bad.rays") && Contains("FRRAYS01"));
    }
    SECTION("counts that disagree with the size") {
        Bytes changed = bytes;
        changed[16] = 2;  // two shadow rays declared, three written
        write_raw(bad, changed);
        CHECK_THAT(read_error(bad), Contains("bad.rays") && Contains("5 records") && Contains("after the last record"));
    }
    SECTION("a tag out of range") {
        Bytes changed = bytes;
        changed[field_offset(4, 7)] = 3;
        write_raw(bad, changed);
        CHECK_THAT(read_error(bad), Contains("bad.rays: record 4 (byte 136)") && Contains("tag 3"));
    }
    SECTION("a tag out of the place its counts give it") {
        Bytes changed = bytes;
        changed[field_offset(1, 7)] = 1;  // a diffuse tag among the primary rays
        write_raw(bad, changed);
        CHECK_THAT(read_error(bad), Contains("bad.rays: record 1") && Contains("tag 1 (diffuse)") &&
                                        Contains("primary"));
    }
    SECTION("a NaN origin") {
        Bytes changed = bytes;
        put_float(changed, field_offset(2, 1), std::numeric_limits<float>::quiet_NaN());
        write_raw(bad, changed);
        CHECK_THAT(read_error(bad), Contains("bad.rays: record 2") && Contains("origin") && Contains("not finite"));
    }
    SECTION("an infinite direction") {
        Bytes changed = bytes;
        put_float(changed, field_offset(0, 4), std::numeric_limits<float>::infinity());
        write_raw(bad, changed);
        CHECK_THAT(read_error(bad), Contains("bad.rays: record 0") && Contains("direction"));
    }
    SECTION("a direction that is not unit length") {
        Bytes changed = bytes;
        put_float(changed, field_offset(3, 3), 2.0f);
        write_raw(bad, changed);
        CHECK_THAT(read_error(bad), Contains("bad.rays: record 3") && Contains("length"));
    }
    SECTION("a NaN tmax") {
        Bytes changed = bytes;
        put_float(changed, field_offset(5, 6), std::numeric_limits<float>::quiet_NaN());
        write_raw(bad, changed);
        CHECK_THAT(read_error(bad), Contains("bad.rays: record 5") && Contains("tmax"));
    }
    SECTION("a negative tmax") {
        Bytes changed = bytes;
        put_float(changed, field_offset(4, 6), -1.0f);
        write_raw(bad, changed);
        CHECK_THAT(read_error(bad), Contains("bad.rays: record 4") && Contains("tmax"));
    }
}

TEST_CASE("FRRAYS01: writing into a folder that does not exist is refused and leaves nothing",
          "[unit][ray-benchmark]") {
    testing::TemporaryFolder folder;
    CHECK_THROWS_WITH(write_ray_batches(folder.file("no/such/folder/batches.rays"), sample_batches()),
                      Contains("does not exist"));
    CHECK(std::filesystem::is_empty(folder.path()));
}

TEST_CASE("FRHITS01: written hits read back bit for bit, in the documented layout", "[unit][ray-benchmark]") {
    testing::TemporaryFolder folder;
    HitFile written;
    written.triangle_count = 100;
    written.primary = {ClosestHit{7, 1.5f}, ClosestHit{}, ClosestHit{99, 3e-7f}};
    written.diffuse = {ClosestHit{0, 123456.75f}, ClosestHit{}};
    write_hit_file(folder.file("out.hits"), written);

    const Bytes bytes = file_bytes(folder.file("out.hits"));
    REQUIRE(bytes.size() == 8 + 12 + 5 * 8);
    CHECK(std::string(bytes.begin(), bytes.begin() + 8) == "FRHITS01");
    CHECK(bytes[8] == 3);
    CHECK(bytes[12] == 2);
    CHECK(bytes[16] == 100);
    // Record 1, a miss: triangle -1 (ff ff ff ff), t = +inf (0x7f800000: 00 00 80 7f).
    CHECK(bytes[28] == 0xff);
    CHECK(bytes[31] == 0xff);
    CHECK(bytes[34] == 0x80);
    CHECK(bytes[35] == 0x7f);

    const HitFile read = read_hit_file(folder.file("out.hits"));
    CHECK(read.triangle_count == 100);
    CHECK(read.primary == written.primary);
    CHECK(read.diffuse == written.diffuse);
}

TEST_CASE("FRHITS01: damaged files are refused, naming the file and the record", "[unit][ray-benchmark]") {
    testing::TemporaryFolder folder;
    HitFile hits;
    hits.triangle_count = 10;
    hits.primary = {ClosestHit{1, 2.0f}, ClosestHit{}};
    hits.diffuse = {ClosestHit{9, 0.5f}};
    write_hit_file(folder.file("good.hits"), hits);
    const Bytes bytes = file_bytes(folder.file("good.hits"));
    const std::string bad = folder.file("bad.hits");
    auto error_of = [&](const Bytes& changed) {
        write_raw(bad, changed);
        try {
            read_hit_file(bad);
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("(no error)");
    };

    SECTION("truncated") { CHECK_THAT(error_of(Bytes(bytes.begin(), bytes.end() - 1)), Contains("bad.hits") && Contains("bytes")); }
    SECTION("a wrong magic") {
        Bytes changed = bytes;
        changed[0] = 'X';
        CHECK_THAT(error_of(changed), Contains("bad.hits") && Contains("FRHITS01"));
    }
    SECTION("a triangle index past the triangle count") {
        Bytes changed = bytes;
        changed[20 + 2 * 8] = 10;  // record 2's triangle: 10 of 10 triangles
        CHECK_THAT(error_of(changed), Contains("bad.hits: record 2") && Contains("triangle 10"));
    }
    SECTION("a miss with a finite t") {
        Bytes changed = bytes;
        put_float(changed, 20 + 1 * 8 + 4, 1.0f);
        CHECK_THAT(error_of(changed), Contains("bad.hits: record 1") && Contains("miss"));
    }
    SECTION("a hit with a NaN t") {
        Bytes changed = bytes;
        put_float(changed, 20 + 4, std::numeric_limits<float>::quiet_NaN());
        CHECK_THAT(error_of(changed), Contains("bad.hits: record 0") && Contains("hit"));
    }
}
