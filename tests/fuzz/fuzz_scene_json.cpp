// libFuzzer target fuzz_scene_json: see fuzz_entry_points.hpp for what it loads and what counts as a
// finding, and README.md for how to run it.
#include "fuzz_entry_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    freezeray::fuzzing::run_scene_json(data, size);  // InputError is caught there; anything else escapes
    return 0;
}
