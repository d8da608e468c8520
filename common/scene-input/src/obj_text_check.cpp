// The first pass over an OBJ file's text: see obj_text_check.hpp for why it exists.
#include "freezeray/obj_text_check.hpp"

#include "freezeray/error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <system_error>

namespace freezeray::obj_detail {
namespace {

// One line of the file, to name in messages. The "file.obj:LINE" string is only built when
// there is something to report: most of a large file's lines have nothing wrong.
struct LineRef {
    const std::string& path;
    std::size_t number;
    std::string where() const { return path + ":" + std::to_string(number); }
};

// True when the whole word is an integer ("12", "-3"); stores it.
bool parse_integer(std::string_view word, long long& value) {
    if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
    const char* last = word.data() + word.size();
    const auto [end, error] = std::from_chars(word.data(), last, value);
    return error == std::errc() && end == last;
}

// Checks that a v, vt or vn line has between `least` and `most` numbers, all well formed;
// `expected` says which in words. Returns false when one of the first three is nan or inf.
bool check_coordinates(const std::vector<std::string_view>& words, std::size_t least, std::size_t most,
                       const char* expected, const LineRef& line) {
    const std::size_t count = words.size() - 1;
    const std::string_view keyword = words[0];
    if (count < least || count > most)
        throw InputError(line.where(), "a '" + std::string(keyword) + "' line needs " + expected + ", found " +
                                           std::to_string(count) + " numbers");
    bool finite = true;
    for (std::size_t i = 1; i < words.size(); ++i) {
        double value = 0.0;
        if (!parse_number(words[i], value))
            throw InputError(line.where(), "'" + std::string(words[i]) + "' on a '" + std::string(keyword) +
                                               "' line is not a number");
        if (i <= 3 && !std::isfinite(value)) finite = false;
    }
    return finite;
}

// Checks a `vw` line (vertex weights, a tinyobjloader extension the renderer ignores):
// tinyobjloader converts its joint ids to int without a check (found by fuzz_obj: an infinite
// one), so every value must be a number within the range of an int.
void check_vertex_weights(const std::vector<std::string_view>& words, const LineRef& line) {
    for (std::size_t i = 1; i < words.size(); ++i) {
        std::string_view word = words[i];
        if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
        double value = 0.0;
        const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (error != std::errc() || end != word.data() + word.size() || !(std::abs(value) <= 2147483647.0))
            throw InputError(line.where(), "'" + std::string(words[i]) +
                                               "' on a 'vw' line is not a number within the range of an int");
    }
}

// How many vertices, texture coordinates and normals the file has defined up to a line.
struct DefinedCounts {
    std::size_t positions = 0;
    std::size_t texture_coordinates = 0;
    std::size_t normals = 0;
};

// Checks one index of a face vertex. OBJ indices start at 1; negative ones count back from the
// last element defined so far (-1 is the latest), which is how tinyobjloader reads them too.
void check_index(long long index, std::size_t defined, const char* index_kind, const char* element_name,
                 const LineRef& line) {
    const long long count = static_cast<long long>(defined);
    if (index == 0)
        throw InputError(line.where(), std::string(index_kind) + " 0 is invalid (OBJ indices start at 1)");
    if (index > count || index < -count)
        throw InputError(line.where(), std::string(index_kind) + " " + std::to_string(index) +
                                           " is out of range (the file has " + std::to_string(count) + " " +
                                           element_name + ")");
}

// Which indices a face vertex names: "v", "v/vt", "v//vn" or "v/vt/vn".
enum class FaceVertexForm { position, position_uv, position_normal, position_uv_normal };

// Checks one face vertex word such as "3/7/2" and returns which indices it names.
FaceVertexForm check_face_vertex(std::string_view word, const DefinedCounts& defined, const LineRef& line) {
    const std::size_t part_count = 1 + static_cast<std::size_t>(std::count(word.begin(), word.end(), '/'));
    std::string_view parts[3];
    if (part_count <= 3) {
        std::string_view rest = word;
        for (std::size_t i = 0; i + 1 < part_count; ++i) {
            const std::size_t slash = rest.find('/');
            parts[i] = rest.substr(0, slash);
            rest.remove_prefix(slash + 1);
        }
        parts[part_count - 1] = rest;
    }
    long long position = 0, uv = 0, normal = 0;
    const bool has_uv = part_count >= 2 && !parts[1].empty();
    const bool has_normal = part_count == 3;
    const bool well_formed = part_count <= 3 && parse_integer(parts[0], position) &&
                             (!has_uv || parse_integer(parts[1], uv)) &&
                             (part_count != 2 || has_uv) && (!has_normal || parse_integer(parts[2], normal));
    if (!well_formed)
        throw InputError(line.where(), "'" + std::string(word) +
                                           "' is not a face vertex (expected v, v/vt, v//vn or v/vt/vn with "
                                           "whole numbers)");

    check_index(position, defined.positions, "face index", "vertices", line);
    if (has_uv)
        check_index(uv, defined.texture_coordinates, "face texture coordinate index", "texture coordinates", line);
    if (has_normal) check_index(normal, defined.normals, "face normal index", "normals", line);
    if (has_uv && has_normal) return FaceVertexForm::position_uv_normal;
    if (has_uv) return FaceVertexForm::position_uv;
    if (has_normal) return FaceVertexForm::position_normal;
    return FaceVertexForm::position;
}

// Checks an `f` line: 3 to 255 vertices, each well formed and in range, all written in
// the same form. A line cut short at the end of a truncated file usually breaks one of these.
void check_face(const std::vector<std::string_view>& words, const DefinedCounts& defined, const LineRef& line) {
    const std::size_t vertex_count = words.size() - 1;
    if (vertex_count < 3)
        throw InputError(line.where(), "a face needs at least 3 vertices, found " + std::to_string(vertex_count));
    // tinyobjloader stores a face's vertex count in an unsigned char.
    if (vertex_count > 255)
        throw InputError(line.where(), "a face has " + std::to_string(vertex_count) +
                                           " vertices; at most 255 are supported");
    const FaceVertexForm first_form = check_face_vertex(words[1], defined, line);
    for (std::size_t i = 2; i < words.size(); ++i) {
        if (check_face_vertex(words[i], defined, line) != first_form)
            throw InputError(line.where(), "face vertex '" + std::string(words[i]) + "' names other indices than '" +
                                               std::string(words[1]) +
                                               "' (the vertices of a face are all written alike); is the line cut "
                                               "short?");
    }
}

// The file names of an `mtllib` line, split at spaces; "\ " is a space inside a name (the
// escape tinyobjloader understands).
std::vector<std::string> mtllib_file_names(std::string_view arguments) {
    std::vector<std::string> names;
    std::string current;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const char c = arguments[i];
        if (c == '\\' && i + 1 < arguments.size()) {
            current += arguments[++i];
        } else if (c == ' ' || c == '\t' || c == '\r') {
            if (!current.empty()) names.push_back(current);
            current.clear();
        } else {
            current += c;
        }
    }
    if (!current.empty()) names.push_back(current);
    return names;
}

}  // namespace

bool read_text_file(const std::string& path, std::string& text) {
    std::ifstream file(path, std::ios::binary);
    if (!file) return false;
    file.seekg(0, std::ios::end);
    const std::streamoff size = file.tellg();
    if (size < 0) return false;
    file.seekg(0, std::ios::beg);
    const std::size_t old_size = text.size();
    text.resize(old_size + static_cast<std::size_t>(size));
    file.read(text.data() + old_size, size);
    return static_cast<bool>(file);
}

std::string_view next_line(std::string_view text, std::size_t& start) {
    std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    start = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
    return line.substr(0, line.find('\0'));
}

void refuse_huge_exponents(std::string_view line, const std::string& path, std::size_t line_number) {
    for (std::size_t i = 1; i + 1 < line.size(); ++i) {
        const char before = line[i - 1];
        if ((line[i] != 'e' && line[i] != 'E') || !((before >= '0' && before <= '9') || before == '.')) continue;
        std::size_t digit = i + 1;
        if (line[digit] == '+' || line[digit] == '-') ++digit;
        while (digit < line.size() && line[digit] == '0') ++digit;  // leading zeros do not count
        std::size_t end = digit;
        while (end < line.size() && line[end] >= '0' && line[end] <= '9') ++end;
        if (end - digit > 6) {
            const std::size_t start = line.find_last_of(" \t", i) == std::string_view::npos ? 0 : line.find_last_of(" \t", i) + 1;
            throw InputError(path + ":" + std::to_string(line_number),
                             "'" + std::string(line.substr(start, line.find_first_of(" \t", i) - start)) +
                                 "' has an exponent too large to read");
        }
    }
}

// Splits one line into words separated by spaces or tabs; a word starting with '#' begins a
// comment, which ends the line.
void split_words(std::string_view line, std::vector<std::string_view>& words) {
    words.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        if (i == line.size() || line[i] == '#') return;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        words.push_back(line.substr(start, i - start));
    }
}

// True when the whole word is a decimal number ("1", "-0.5", "+2e-3", "nan", "inf"); stores it.
bool parse_number(std::string_view word, double& value) {
    // std::from_chars does not accept a leading '+', which some exporters write.
    if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
    const char* last = word.data() + word.size();
    const auto [end, error] = std::from_chars(word.data(), last, value);
    // Too large or too small for a double (1e999) is still a number as far as syntax goes.
    // tinyobjloader makes it inf or 0, and an inf vertex makes its triangles degenerate.
    if (error == std::errc::result_out_of_range) value = 0.0;
    else if (error != std::errc()) return false;
    return end == last;
}

ObjTextSummary check_obj_text(std::string_view text, const std::string& path) {
    ObjTextSummary summary;
    DefinedCounts defined;
    std::vector<std::string_view> words;
    std::size_t line_number = 0;
    for (std::size_t start = 0; start < text.size();) {
        const std::string_view text_line = next_line(text, start);
        ++line_number;
        const LineRef line{path, line_number};

        refuse_huge_exponents(text_line, path, line_number);
        split_words(text_line, words);
        if (words.empty()) continue;
        const std::string_view keyword = words[0];
        if (keyword == "v") {
            if (!check_coordinates(words, 3, 7, "x y z (then optionally w, or r g b)", line))
                summary.non_finite_positions.push_back(defined.positions);
            ++defined.positions;
        } else if (keyword == "vt") {
            check_coordinates(words, 1, 3, "u (then optionally v and w)", line);
            ++defined.texture_coordinates;
        } else if (keyword == "vn") {
            check_coordinates(words, 3, 3, "x y z", line);
            ++defined.normals;
        } else if (keyword == "vw") {
            check_vertex_weights(words, line);
        } else if (keyword == "f") {
            check_face(words, defined, line);
            ++summary.face_count;
        } else if (keyword == "mtllib") {
            const auto arguments_start = static_cast<std::size_t>(keyword.data() + keyword.size() - text_line.data());
            summary.mtllibs.push_back({line_number, mtllib_file_names(text_line.substr(arguments_start))});
        } else if (keyword == "usemtl") {
            if (words.size() < 2) throw InputError(line.where(), "'usemtl' needs a material name");
            summary.usemtls.push_back({line_number, std::string(words[1])});
        }
        // Other statements (o, g, s, l, p, ...) are tinyobjloader's to read.
    }
    return summary;
}

}  // namespace freezeray::obj_detail
