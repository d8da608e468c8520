// What the stability tests share: rendering a hard case of scenes/hard/, the validity check every
// render must pass (no NaN, Inf or negative value), the classification of pixels by what they
// see, and the energy tests: "every pixel is this value" and "no pixel exceeds it" (one-sample,
// over blocks and pixel groups), and "two renders agree within a tolerance" (two-sample).
#pragma once

#include "image_tests.hpp"
#include "statistics.hpp"

#include "freezeray/integrator.hpp"
#include "freezeray/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace freezeray::stability {

// The level of one statistical test of the stability label (tests/STATISTICS.md, its table): a
// two-sample test passes this; a one-sample test passes a tenth of it and counts as ten tests.
inline constexpr double stability_test_alpha = 5e-8;
inline constexpr double one_sample_stability_alpha = stability_test_alpha / 10.0;

// Absolute path of scenes/hard/<relative>.
std::string hard_scene(const std::string& relative);

// The integrators that exist today; each hard case is rendered by every one of them.
const std::vector<std::string>& all_integrators();

struct HardRender {
    std::string scene;           // relative to scenes/hard/
    std::string integrator = "pt-is";
    std::uint64_t samples_per_pixel = 64;
    std::uint64_t seed = 1;
    int max_depth = 0;           // 0: the scene's, else the integrator's
    int size = 0;                // width and height; 0: the scene's
};

// Loads and renders quietly, on one thread (the stability label's CPU budget is per core).
RenderResult render(const HardRender& request);

// Loads a hard case (for pixel classification and direct ray queries).
Scene load(const std::string& relative, int size = 0);

// Fails (CHECK) unless the render counted no invalid sample and every pixel of its mean and
// variance is finite and non-negative. `what` names the case and integrator in the message.
void check_valid(const RenderResult& result, const std::string& what);

// What each pixel sees, from 5x5 rays spread over its area: the index of the mesh (into
// Scene::meshes) all of them hit, Mixed when they hit different meshes or some miss, Nothing
// when all miss. A pixel of one mesh sees only that mesh; a Mixed one is a silhouette pixel.
inline constexpr int Mixed = -2;
inline constexpr int Nothing = -1;
std::vector<int> pixel_coverage(const Scene& scene);

// The pixels (indices y * width + x) whose coverage is `value`.
std::vector<std::size_t> pixels_where(const std::vector<int>& coverage, int value);

// A group of pixels tested together (besides the blocks): e.g. the silhouette pixels.
struct PixelGroup {
    std::string name;
    std::vector<std::size_t> pixels;
};

enum class Expectation {
    Equal,   // the true mean of every block and group is `known`
    AtMost,  // the true mean of every block and group is at most `known` (one-sided)
};

struct EnergyTestResult {
    bool passed = true;
    std::string message;  // the verdict, the levels and the worst block or group
};

// Tests every block_size x block_size block (none if block_size is 0) and every group, per channel, with the one-sample
// t-test against `known` (two-sided for Equal, one-sided for AtMost), Šidák-corrected over all of
// them to a false-failure rate of `alpha`. Pixels whose mean is within a relative 1e-5 of `known`
// and whose standard error is below that are taken as exactly `known`: float rounding of a
// deterministic estimate (a weight of 0.99999994 instead of 1) is not a bias to detect.
EnergyTestResult energy_test(const RenderResult& result, double known, Expectation expectation, int block_size,
                             const std::vector<PixelGroup>& groups, double alpha);

// Tests that two renders with independent seeds agree within a relative `tolerance` in every
// block_size x block_size block and channel: Welch's t-test of the block means, after moving the
// second towards the first by up to tolerance x the larger of the two (an equivalence margin),
// Šidák-corrected over blocks x channels to `alpha`. With tolerance 0 it is the blockwise Welch test.
EnergyTestResult agreement_test(const RenderResult& a, const RenderResult& b, double tolerance, int block_size,
                                double alpha);

// On failure: writes the renders (and their variances) as evidence under the test's name and
// returns the folder, to be printed with the message.
std::string write_evidence(const std::string& test_name, const std::string& report,
                           const std::vector<std::pair<std::string, const RenderResult*>>& renders);

}  // namespace freezeray::stability
