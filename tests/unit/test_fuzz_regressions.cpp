// Replays every input the fuzzers found a problem with (tests/fuzz/regressions/<target>/), and
// their seed corpora (tests/fuzz/corpus/<target>/), through the fuzz targets' own entry points
// with the normal compiler: each must load or be refused with InputError, nothing else. A crash
// here is the regression itself. How the inputs were found: tests/fuzz/README.md.
#include "../fuzz/fuzz_entry_points.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace {

namespace fs = std::filesystem;
using freezeray::fuzzing::Outcome;
using EntryPoint = Outcome (*)(const std::uint8_t*, std::size_t);

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The files of tests/fuzz/<kind>/<target>/, in name order.
std::vector<fs::path> inputs(const std::string& kind, const std::string& target) {
    const fs::path folder = fs::path(FREEZERAY_SOURCE_DIR) / "tests" / "fuzz" / kind / target;
    std::vector<fs::path> files;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
        if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// Runs every input of a target; returns how many were replayed.
std::size_t replay(const std::string& kind, const std::string& target, EntryPoint entry_point) {
    const std::vector<fs::path> files = inputs(kind, target);
    for (const fs::path& file : files) {
        INFO(kind << "/" << target << "/" << file.filename().string());
        const std::vector<std::uint8_t> bytes = read_bytes(file);
        try {
            entry_point(bytes.data(), bytes.size());  // loaded or refused with InputError: both fine
        } catch (const std::exception& e) {
            FAIL("neither loaded nor refused with InputError: " << e.what());
        }
    }
    return files.size();
}

struct Target {
    const char* name;
    EntryPoint entry_point;
};

const Target targets[] = {{"scene_json", freezeray::fuzzing::run_scene_json},
                          {"obj", freezeray::fuzzing::run_obj},
                          {"image", freezeray::fuzzing::run_image}};

}  // namespace

TEST_CASE("inputs the fuzzers found are loaded or refused with InputError, nothing else", "[unit][fuzz]") {
    for (const Target& target : targets) {
        DYNAMIC_SECTION(target.name) { replay("regressions", target.name, target.entry_point); }
    }
}

TEST_CASE("the fuzzers' seed inputs are loaded or refused with InputError, nothing else", "[unit][fuzz]") {
    for (const Target& target : targets) {
        DYNAMIC_SECTION(target.name) { CHECK(replay("corpus", target.name, target.entry_point) > 0); }
    }
}

// The harness itself: a valid seed loads and a broken one is refused, so that a fuzz target
// which refused everything (a wrong path, a missing fixture) cannot pass unnoticed.
TEST_CASE("the fuzz entry points load valid seeds and refuse broken ones", "[unit][fuzz]") {
    auto outcome = [](const std::string& target, const std::string& file, EntryPoint entry_point) {
        const std::vector<std::uint8_t> bytes =
            read_bytes(fs::path(FREEZERAY_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / target / file);
        REQUIRE(!bytes.empty());
        return entry_point(bytes.data(), bytes.size());
    };
    using namespace freezeray::fuzzing;
    CHECK(outcome("scene_json", "full.json", run_scene_json) == Outcome::loaded);
    CHECK(outcome("scene_json", "material-2.json", run_scene_json) == Outcome::loaded);  // a PNG texture
    CHECK(outcome("scene_json", "malformed.json", run_scene_json) == Outcome::refused);
    CHECK(outcome("obj", "objects-mtl.obj", run_obj) == Outcome::loaded);
    CHECK(outcome("obj", "quad-mtl.obj", run_obj) == Outcome::loaded);
    CHECK(outcome("obj", "truncated.obj", run_obj) == Outcome::refused);
    for (const char* file : {"exr-zip-float.bin", "exr-piz-half.bin", "exr-tiled.bin", "exr-mipmap-zip.bin",
                             "exr-b44-half.bin", "exr-dwab-float.bin", "pfm-rgb.bin", "hdr-rle.bin",
                             "png-rgb8.bin", "png-grey16.bin", "bmp.bin", "tga.bin"})
        CHECK(outcome("image", file, run_image) == Outcome::loaded);
    for (const char* file : {"exr-truncated.bin", "pfm-truncated.bin", "hdr-truncated.bin", "png-truncated.bin"})
        CHECK(outcome("image", file, run_image) == Outcome::refused);
}
