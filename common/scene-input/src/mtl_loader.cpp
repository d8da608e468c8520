// Reading one MTL file: tinyobjloader's values plus what the renderer needs besides them.
#include "mtl_loader.hpp"

#include "freezeray/error.hpp"
#include "freezeray/obj_text_check.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string_view>

namespace freezeray::obj_detail {
namespace {

namespace fs = std::filesystem;

// One statement of a `newmtl` block, remembered so that the values tinyobjloader parsed can be
// matched with what the file wrote.
struct Statement {
    std::size_t line = 0;
    std::size_t argument_count = 0;  // words after the keyword: "Kd 0.5" has 1
};

// One `newmtl` block as written.
struct MtlBlock {
    std::string name;
    std::size_t line = 0;
    // The last statement of each keyword in the block (tinyobjloader keeps the last value too).
    std::map<std::string, Statement, std::less<>> statements;

    const Statement* find(std::string_view keyword) const {
        const auto found = statements.find(keyword);
        return found == statements.end() ? nullptr : &found->second;
    }
};

// Keywords that tinyobjloader reads as the same statement are recorded under one name.
std::string_view canonical_keyword(std::string_view keyword) {
    if (keyword == "Kt") return "Tf";
    if (keyword == "map_Bump" || keyword == "bump") return "map_bump";
    return keyword;
}

bool is_one_of(std::string_view word, std::initializer_list<std::string_view> list) {
    for (const std::string_view item : list)
        if (word == item) return true;
    return false;
}

// Checks the arguments of the statements whose values the renderer uses. tinyobjloader reads
// a malformed number as 0 without a word, and "d -halo 0.5" as d = 0 (fully transparent).
void check_values(const std::vector<std::string_view>& words, const std::string& where) {
    const std::string keyword(words[0]);
    const bool is_color = is_one_of(keyword, {"Ka", "Kd", "Ks", "Ke", "Tf", "Kt"});
    const bool is_scalar = is_one_of(keyword, {"Ns", "Ni", "d", "Tr", "Pr", "Pm", "illum"});
    if (!is_color && !is_scalar) return;

    const std::size_t count = words.size() - 1;
    if (is_color && count >= 1 && (words[1] == "spectral" || words[1] == "xyz"))
        throw InputError(where, "'" + keyword + " " + std::string(words[1]) + "' is not supported: write " + keyword +
                                    " r g b");
    if (is_color && count != 1 && count != 3)
        throw InputError(where, "'" + keyword + "' needs 1 or 3 numbers, found " + std::to_string(count));
    if (is_scalar && count != 1)
        throw InputError(where, "'" + keyword + "' needs 1 number, found " + std::to_string(count));
    for (std::size_t i = 1; i < words.size(); ++i) {
        double value = 0.0;
        const bool integer_wanted = keyword == "illum";
        if (!parse_number(words[i], value) || (integer_wanted && value != std::floor(value)))
            throw InputError(where, "'" + std::string(words[i]) + "' on a '" + keyword + "' line is not " +
                                        (integer_wanted ? "a whole number" : "a number"));
    }
}

// Finds the `newmtl` blocks of an MTL file, the statements each one writes and their lines,
// and checks the values the renderer uses. Statements before the first `newmtl` belong to no
// material (tinyobjloader drops them too).
std::vector<MtlBlock> scan_mtl_blocks(std::string_view text, const std::string& path) {
    std::vector<MtlBlock> blocks;
    std::vector<std::string_view> words;
    std::size_t line_number = 0;
    for (std::size_t start = 0; start < text.size();) {
        const std::string_view line = next_line(text, start);
        ++line_number;

        refuse_huge_exponents(line, path, line_number);
        split_words(line, words);
        if (words.empty()) continue;
        const std::string where = path + ":" + std::to_string(line_number);
        if (words[0] == "newmtl") {
            // The name is the rest of the line, spaces included, as tinyobjloader reads it.
            std::string_view name = line.substr(static_cast<std::size_t>(words[0].data() - line.data()) + 6);
            const std::size_t first = name.find_first_not_of(" \t");
            const std::size_t last = name.find_last_not_of(" \t\r");
            if (first == std::string_view::npos) throw InputError(where, "'newmtl' needs a material name");
            name = name.substr(first, last - first + 1);
            blocks.push_back(MtlBlock{std::string(name), line_number, {}});
            continue;
        }
        if (blocks.empty()) continue;
        check_values(words, where);
        blocks.back().statements[std::string(canonical_keyword(words[0]))] = Statement{line_number, words.size() - 1};
    }
    return blocks;
}

// The colour a Kd, Ks, Ke or Tf statement wrote. The MTL format lets "Kd 0.5" stand for
// "Kd 0.5 0.5 0.5"; tinyobjloader reads it as (0.5, 0, 0), so a single value is repeated here.
Spectrum written_color(const tinyobj::real_t (&rgb)[3], const Statement& statement) {
    if (statement.argument_count == 1) return Spectrum(rgb[0]);
    return Spectrum(rgb[0], rgb[1], rgb[2]);
}

// The absolute path of the texture file a map statement names, relative to the MTL file's
// folder; empty when the block has no such statement. Throws when the file does not exist.
std::string texture_path(const std::string& file_name, std::string_view keyword, const MtlBlock& block,
                         const std::string& mtl_path) {
    const Statement* statement = block.find(keyword);
    if (statement == nullptr) return {};
    const std::string where = mtl_path + ":" + std::to_string(statement->line);
    if (file_name.empty()) throw InputError(where, "'" + std::string(keyword) + "' names no texture file");

    const fs::path resolved = fs::absolute(fs::path(mtl_path).parent_path() / fs::path(file_name)).lexically_normal();
    std::error_code error;
    if (!fs::is_regular_file(resolved, error))
        throw InputError(where, "texture file '" + file_name + "' of '" + std::string(keyword) +
                                    "' does not exist (looked for " + resolved.string() + ")");
    return resolved.string();
}

// Combines tinyobjloader's values for one block with what the block wrote. A value the block
// does not write keeps the default of MtlMaterial (obj_loader.hpp), not tinyobjloader's: for
// example a missing `illum` stays 2 and a missing `Tf` stays 1 (tinyobjloader: 0 and 0).
MtlMaterial to_mtl_material(const tinyobj::material_t& parsed, const MtlBlock& block, const std::string& mtl_path) {
    MtlMaterial material;
    material.name = block.name;
    material.where = mtl_path + ":" + std::to_string(block.line);
    if (const Statement* s = block.find("Kd")) material.kd = written_color(parsed.diffuse, *s);
    if (const Statement* s = block.find("Ks")) material.ks = written_color(parsed.specular, *s);
    if (const Statement* s = block.find("Ke")) material.ke = written_color(parsed.emission, *s);
    if (const Statement* s = block.find("Tf")) material.tf = written_color(parsed.transmittance, *s);
    if (block.find("Ns")) material.ns = parsed.shininess;
    if (block.find("Ni")) material.ni = parsed.ior;
    if (block.find("d") || block.find("Tr")) material.dissolve = parsed.dissolve;  // d wins over Tr = 1 - d
    if (block.find("illum")) material.illum = parsed.illum;
    if (block.find("Pr")) material.pr = parsed.roughness;
    if (block.find("Pm")) material.pm = parsed.metallic;

    material.map_kd = texture_path(parsed.diffuse_texname, "map_Kd", block, mtl_path);
    material.map_ks = texture_path(parsed.specular_texname, "map_Ks", block, mtl_path);
    material.map_ns = texture_path(parsed.specular_highlight_texname, "map_Ns", block, mtl_path);
    material.map_pr = texture_path(parsed.roughness_texname, "map_Pr", block, mtl_path);
    material.map_pm = texture_path(parsed.metallic_texname, "map_Pm", block, mtl_path);
    material.map_bump = texture_path(parsed.bump_texname, "map_bump", block, mtl_path);
    material.map_d = texture_path(parsed.alpha_texname, "map_d", block, mtl_path);
    return material;
}

}  // namespace

void load_mtl_file(const std::string& path, MtlLibrary& library) {
    std::string text;
    if (!read_text_file(path, text)) throw InputError(path, "the MTL file cannot be read");
    const std::vector<MtlBlock> blocks = scan_mtl_blocks(text, path);

    std::map<std::string, int> parsed_by_name;
    std::vector<tinyobj::material_t> parsed;
    std::istringstream stream(text);
    std::string warning, error;
    tinyobj::LoadMtl(&parsed_by_name, &parsed, &stream, &warning, &error);

    // tinyobjloader adds one material per `newmtl`, in order, and one unnamed material for a
    // file without any `newmtl`, which stands for nothing here.
    if (blocks.empty()) return;
    if (parsed.size() != blocks.size())
        throw InputError(path, "tinyobjloader read " + std::to_string(parsed.size()) + " materials but the file has " +
                                   std::to_string(blocks.size()) + " newmtl lines");

    for (std::size_t i = 0; i < blocks.size(); ++i) {
        MtlMaterial material = to_mtl_material(parsed[i], blocks[i], path);
        const int index = static_cast<int>(library.materials.size());
        const auto [first, inserted] = library.index_by_name.emplace(material.name, index);
        if (!inserted)
            library.warnings.push_back(material.where + ": material '" + material.name +
                                       "' is defined again; usemtl selects its first definition (" +
                                       library.materials[static_cast<std::size_t>(first->second)].where + ")");
        library.materials.push_back(std::move(material));
        library.parsed.push_back(parsed[i]);
    }
}

}  // namespace freezeray::obj_detail
