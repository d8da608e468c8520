// The entry points of the fuzz targets, shared by the libFuzzer executables (tests/fuzz/) and by
// the regression test that replays their crashers (tests/unit/test_fuzz_regressions.cpp).
//
// Each entry point takes the bytes of one input, writes them where a loader reads files (a
// private temporary folder that also holds small valid files to refer to) and runs the loader.
// The only acceptable outcomes are success and freezeray::InputError. Anything else is a
// finding: a crash or sanitizer report, another exception, a hang, a leak, or a loaded result
// that breaks an invariant the renderer relies on (checked here; reported as std::logic_error).
// Header-only, so that the regression test needs no extra source file.
#pragma once

#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/registry.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <unistd.h>  // getpid, to name the temporary folder

namespace freezeray::fuzzing {

enum class Outcome { loaded, refused };  // refused: the loader threw InputError

// The folder the inputs are written to, with the files an input may refer to:
//   tri.obj, tri.mtl         a triangle and a tetrahedron face with materials 'paint' and 'lamp'
//   texture.{png,pfm,hdr,exr} a 2x2 image in each format, for *_texture keys and map_* lines
// Created on first use, removed at exit.
class Workspace {
public:
    Workspace() {
        namespace fs = std::filesystem;
        folder_ = (fs::temp_directory_path() / ("freezeray-fuzz-" + std::to_string(::getpid()))).string();
        fs::create_directories(folder_);
        write("tri.obj",
              "mtllib tri.mtl\n"
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
              "vt 0 0\nvt 1 0\nvt 0 1\n"
              "vn 0 0 1\n"
              "o triangle\nusemtl paint\nf 1/1/1 2/2/1 3/3/1\n"
              "o side\nusemtl lamp\nf 1 3 4\n");
        write("tri.mtl", "newmtl paint\nKd 0.5 0.25 0.125\nmap_Kd texture.png\n\nnewmtl lamp\nKd 0 0 0\nKe 2 2 2\n");
        Image texture(2, 2, Spectrum(0.25f, 0.5f, 0.75f));
        texture.at(1, 0) = Spectrum(1.0f, 0.0f, 0.0f);
        for (const char* extension : {".png", ".pfm", ".hdr", ".exr"})
            write_image(file(std::string("texture") + extension), texture);
    }
    ~Workspace() {
        std::error_code ignored;
        std::filesystem::remove_all(folder_, ignored);
    }
    Workspace(const Workspace&) = delete;
    Workspace& operator=(const Workspace&) = delete;

    std::string file(const std::string& name) const { return folder_ + "/" + name; }

    // Writes `bytes` to the file `name` of the folder and returns its path.
    std::string write(const std::string& name, std::string_view bytes) const {
        const std::string path = file(name);
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!out) throw std::runtime_error("fuzz workspace: cannot write " + path);
        return path;
    }

    void remove(const std::string& name) const {
        std::error_code ignored;
        std::filesystem::remove(file(name), ignored);
    }

private:
    std::string folder_;
};

inline const Workspace& workspace() {
    static const Workspace instance;
    return instance;
}

// What `freezeray` registers: chapters 01 and 02.
inline const Registry& fuzz_registry() {
    static const Registry registry = [] {
        Registry r("freezeray", 2);
        register_chapter02(r);
        return r;
    }();
    return registry;
}

// Throws std::logic_error (a finding, not a refusal) when `holds` is false.
inline void require_invariant(bool holds, const char* what) {
    if (!holds) throw std::logic_error(std::string("fuzz invariant broken: ") + what);
}

inline bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What the renderer assumes of a loaded scene: indices in range, finite positions, one normal
// and uv per vertex when present, unit normals, a usable camera and accelerator.
inline void check_scene(const Scene& scene) {
    require_invariant(!scene.meshes.empty(), "a loaded scene has a mesh");
    require_invariant(scene.camera != nullptr && scene.accelerator != nullptr, "camera and accelerator exist");
    require_invariant(scene.camera_description.width >= 1 && scene.camera_description.height >= 1,
                      "the resolution is positive");
    for (const TriangleMesh& mesh : scene.meshes) {
        require_invariant(mesh.triangle_count() > 0, "every mesh has a triangle");
        require_invariant(mesh.face_materials.size() == mesh.triangles.size(), "one material per triangle");
        require_invariant(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size(), "one normal per vertex");
        require_invariant(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size(), "one uv per vertex");
        for (const Vec3& p : mesh.positions) require_invariant(is_finite(p), "positions are finite");
        for (const Vec3& n : mesh.normals)
            require_invariant(is_finite(n) && std::abs(glm::length(n) - 1.0f) < 1e-3f, "normals have unit length");
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            for (const std::uint32_t v : mesh.triangles[t])
                require_invariant(v < mesh.positions.size(), "vertex indices are in range");
            require_invariant(mesh.face_materials[t] < scene.materials.size(), "material indices are in range");
        }
    }
    for (const EmissiveTriangle& e : scene.emissive_triangles)
        require_invariant(e.mesh < scene.meshes.size() && e.triangle < scene.meshes[e.mesh].triangle_count(),
                          "emissive triangles exist");
}

// fuzz_scene_json: the input is a scene.json beside tri.obj, tri.mtl and the textures.
inline Outcome run_scene_json(const std::uint8_t* data, std::size_t size) {
    const Workspace& w = workspace();
    const std::string path = w.write("scene.json", {reinterpret_cast<const char*>(data), size});
    try {
        const Scene scene = load_scene(path, fuzz_registry());
        check_scene(scene);
        return Outcome::loaded;
    } catch (const InputError&) {
        return Outcome::refused;
    }
}

// The line that separates the OBJ part of an fuzz_obj input from its MTL part.
inline constexpr std::string_view mtl_marker = "\n#MTL\n";

// fuzz_obj: the input is fuzz.obj, or fuzz.obj and fuzz.mtl split at the line "#MTL" (without
// that line there is no fuzz.mtl). It is loaded as a scene would load it (load_obj, then the
// MTL materials through the registry, then the accelerator), from a fixed scene.json.
inline Outcome run_obj(const std::uint8_t* data, std::size_t size) {
    const Workspace& w = workspace();
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const std::size_t marker = input.find(mtl_marker);
    w.write("fuzz.obj", input.substr(0, marker));
    if (marker == std::string_view::npos)
        w.remove("fuzz.mtl");
    else
        w.write("fuzz.mtl", input.substr(marker + mtl_marker.size()));
    static const std::string scene_path =
        w.write("obj-scene.json", R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0],
            "fov_vertical_degrees": 40, "resolution": [4, 4]}, "meshes": [{"file": "fuzz.obj"}]})");
    try {
        const Scene scene = load_scene(scene_path, fuzz_registry());
        check_scene(scene);
        return Outcome::loaded;
    } catch (const InputError&) {
        return Outcome::refused;
    }
}

// fuzz_image: the first byte chooses the extension (byte % 7: .exr, .pfm, .hdr, .png, .jpg,
// .bmp, .tga; the last four share stb_image, which tells PNG, JPEG and BMP by their content);
// the rest is the file.
inline Outcome run_image(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return Outcome::refused;
    static const char* const extensions[7] = {".exr", ".pfm", ".hdr", ".png", ".jpg", ".bmp", ".tga"};
    const std::string name = std::string("fuzz") + extensions[data[0] % 7];
    const std::string path = workspace().write(name, {reinterpret_cast<const char*>(data) + 1, size - 1});
    try {
        const Image image = read_image(path);
        require_invariant(image.width() >= 1 && image.height() >= 1, "a read image is not empty");
        require_invariant(image.pixel_count() == static_cast<std::size_t>(image.width()) * image.height(),
                          "the pixel count is width x height");
        return Outcome::loaded;
    } catch (const InputError&) {
        return Outcome::refused;
    }
}

}  // namespace freezeray::fuzzing
