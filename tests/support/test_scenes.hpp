// Helpers for tests that render: paths of the course's scenes, the complete registry, and a
// one-call render.
#pragma once

#include "freezeray/integrator.hpp"
#include "freezeray/registry.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace freezeray::testing {

// Absolute path of a file under the repository's scenes/ folder.
std::string scene_path(const std::string& relative);

// Absolute path of a file under tests/data/.
std::string test_data_path(const std::string& relative);

// The shared large scenes (../shared/scenes or $FREEZERAY_SHARED_SCENES), when present.
std::optional<std::string> shared_scenes_folder();

// A registry with every chapter registered (what `freezeray` has).
const Registry& full_registry();

// The InputError message of loading a scene, or "(no error)" when it loads.
std::string scene_load_error(const std::string& path, const Registry& registry = full_registry());

struct TestRender {
    std::string scene;             // path of the scene JSON
    // An integrator, or "integrator@sampler" as compare's runs name it (pt-mis@sobol), or with a
    // light sampler (pt-mis@bvh, pt-mis@sobol@bvh). Without a sampler, independent samples,
    // whatever the course's default: the tests' per-pixel variances and error estimates assume
    // them; without a light sampler, the integrator's own (chapter 03's by power).
    std::string integrator = "pt-naive";
    std::uint64_t samples_per_pixel = 16;
    std::uint64_t seed = 1;
    int threads = 0;
    int width = 0;                 // 0: the scene's
    int height = 0;
    int max_depth = 0;             // 0: the scene's, else the integrator's default
    bool strategy_images = false;     // bdpt's per-strategy images (--bdpt-strategies; not written)
    std::uint64_t mlt_bootstrap = 0;  // --mlt-bootstrap (0: mlt's default)
    int mlt_chains = 0;               // --mlt-chains (0: mlt's default)
    // --accel (empty: the scene's, else the default). An exercise test of a chapter before 06
    // asks for "bruteforce": the default KD-tree runs chapter 06's exercises, which a student
    // of an earlier chapter has not written yet.
    std::string accelerator;
    // The accelerator's settings, as its flags would give them ({"simd_width": 4}).
    nlohmann::json accelerator_settings = nlohmann::json::object();
    // The texture layout and its settings, as their flags would give them ({"layout": "tiled"}).
    nlohmann::json texture_settings = nlohmann::json::object();
};

// Loads and renders, quietly.
RenderResult render(const TestRender& request);

// A fresh empty folder under the system's temporary folder, removed when the object dies.
class TemporaryFolder {
public:
    TemporaryFolder();
    ~TemporaryFolder();
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;
    const std::string& path() const { return path_; }
    std::string file(const std::string& name) const { return path_ + "/" + name; }
    // Writes `text` to the file `name` in this folder and returns its path.
    std::string write(const std::string& name, const std::string& text) const;

private:
    std::string path_;
};

}  // namespace freezeray::testing
