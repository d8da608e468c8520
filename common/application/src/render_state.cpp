// Saving, reading, checking and merging render states.
#include "freezeray/render_state.hpp"

#include "freezeray/error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace freezeray {

namespace {

nlohmann::json to_json(const RenderStateInfo& info) {
    return {{"scene", info.scene}, {"integrator", info.integrator}, {"sampler", info.sampler}, {"seed", info.seed},
            {"first_sample", info.first_sample}, {"max_depth", info.max_depth},
            {"width", info.width}, {"height", info.height}, {"light_sampler", info.light_sampler},
            {"seconds", info.seconds}};
}

}  // namespace

void write_render_state(const std::string& path, const RenderStateInfo& info, const Film& film) {
    // The header is one line of JSON, then the film's binary state.
    const std::string temporary = path + ".tmp-" + std::to_string(getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw InputError(path, "cannot be written");
        out << to_json(info).dump() << "\n";
        film.write_state(out);
        out.flush();
        if (!out) {
            std::remove(temporary.c_str());
            throw InputError(path, "writing failed (disk full?)");
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::remove(temporary.c_str());
        throw InputError(path, "cannot be replaced: " + error.message());
    }
}

RenderState read_render_state(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "render state does not exist or cannot be read");
    std::string header;
    std::getline(in, header);
    RenderState state;
    try {
        const nlohmann::json j = nlohmann::json::parse(header);
        state.info.scene = j.at("scene").get<std::string>();
        state.info.integrator = j.at("integrator").get<std::string>();
        state.info.seed = j.at("seed").get<std::uint64_t>();
        if (j.contains("sampler")) state.info.sampler = j.at("sampler").get<std::string>();
        if (j.contains("light_sampler")) state.info.light_sampler = j.at("light_sampler").get<std::string>();
        state.info.first_sample = j.at("first_sample").get<std::uint64_t>();
        state.info.max_depth = j.at("max_depth").get<int>();
        state.info.width = j.at("width").get<int>();
        state.info.height = j.at("height").get<int>();
        if (j.contains("seconds")) state.info.seconds = j.at("seconds").get<double>();
    } catch (const nlohmann::json::exception&) {
        throw InputError(path, "is not a FreezeRay render state (its first line is not the expected header)");
    }
    state.film = std::make_shared<const Film>(Film::read_state(in, path));
    if (state.film->width() != state.info.width || state.film->height() != state.info.height)
        throw InputError(path, "is inconsistent: the header and the film differ in size");
    return state;
}

void check_resumable(const RenderStateInfo& saved, const RenderStateInfo& wanted) {
    auto differ = [](const std::string& what, const std::string& was, const std::string& is) {
        throw InputError("--resume", "the saved render has " + what + " " + was + " but this one asks for " + is +
                                         " (resume with the command that started it)");
    };
    if (saved.scene != wanted.scene) differ("scene", saved.scene, wanted.scene);
    if (saved.integrator != wanted.integrator) differ("integrator", saved.integrator, wanted.integrator);
    if (saved.sampler != wanted.sampler) differ("sampler", saved.sampler, wanted.sampler);
    if (saved.light_sampler != wanted.light_sampler) differ("light sampler", saved.light_sampler, wanted.light_sampler);
    if (saved.seed != wanted.seed) differ("seed", std::to_string(saved.seed), std::to_string(wanted.seed));
    if (saved.first_sample != wanted.first_sample)
        differ("sample offset", std::to_string(saved.first_sample), std::to_string(wanted.first_sample));
    if (saved.max_depth != wanted.max_depth)
        differ("maximum depth", std::to_string(saved.max_depth), std::to_string(wanted.max_depth));
    if (saved.width != wanted.width || saved.height != wanted.height)
        differ("size", std::to_string(saved.width) + "x" + std::to_string(saved.height),
               std::to_string(wanted.width) + "x" + std::to_string(wanted.height));
}

}  // namespace freezeray
