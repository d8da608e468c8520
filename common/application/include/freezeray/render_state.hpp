// A render's saved state: what was rendered (scene, integrator, seed, ...) and its film, exactly.
// Written by `--checkpoint` and on interruption, read by `--resume` and `merge`.
#pragma once

#include "freezeray/film.hpp"

#include <cstdint>
#include <memory>
#include <string>

namespace freezeray {

struct RenderStateInfo {
    std::string scene;
    std::string integrator;
    std::string sampler = "independent";  // chapter 09; states written before it have none: independent
    std::uint64_t seed = 0;
    std::uint64_t first_sample = 0;
    int max_depth = 0;
    int width = 0, height = 0;
    // Chapters 03 and 10; empty for an integrator that chooses no light at shading points (and in
    // states written before light samplers were named).
    std::string light_sampler;
    // The render time of the samples in the film, over every run that added to it (a resumed
    // render's image records the total); not compared when resuming. States written before it
    // was kept say 0.
    double seconds = 0.0;
};

struct RenderState {
    RenderStateInfo info;
    std::shared_ptr<const Film> film;
};

// Writes atomically (a temporary file in the same folder, then renamed over `path`), so a power
// cut leaves the old state or the new one, never a torn file. Throws InputError on failure.
void write_render_state(const std::string& path, const RenderStateInfo& info, const Film& film);

// Reads a state; throws InputError naming the file for a missing, foreign or truncated one.
RenderState read_render_state(const std::string& path);

// Throws InputError("--resume", ...) unless `saved` describes the same render as `wanted`
// (scene, integrator, sampler, light sampler, seed, sample offset, depth and size).
void check_resumable(const RenderStateInfo& saved, const RenderStateInfo& wanted);

}  // namespace freezeray
