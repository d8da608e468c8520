// A first pass over the text of an OBJ file, before tinyobjloader reads it. tinyobjloader
// turns a malformed number into 0 and keeps a face index that points past the end of the
// vertex list (reading it later would crash), and its messages carry no line numbers. This
// pass finds those problems with "file.obj:LINE" and collects the lines the loader needs to
// report later problems (a missing MTL file, an unknown material) where they are written.
// Used by obj_loader.cpp and by the ray benchmark's loader
// (chapters/06-kd-tree/benchmark/benchmark_mesh.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace freezeray::obj_detail {

// An `mtllib` line: the MTL file names it lists, as written.
struct MtllibStatement {
    std::size_t line = 0;
    std::vector<std::string> file_names;
};

// A `usemtl` line: the material it selects for the faces that follow.
struct UsemtlStatement {
    std::size_t line = 0;
    std::string material_name;
};

struct ObjTextSummary {
    std::vector<MtllibStatement> mtllibs;
    std::vector<UsemtlStatement> usemtls;
    // 0-based indices of the `v` lines whose coordinates are written as nan or inf.
    // tinyobjloader reads those words as 0, so the loader puts the real value back.
    std::vector<std::size_t> non_finite_positions;
    std::size_t face_count = 0;
};

// Small text helpers, shared with the MTL reader.

// Reads a whole file into `text` (appending to what it holds); false when it cannot be read.
bool read_text_file(const std::string& path, std::string& text);

// The next line of an OBJ or MTL text from `start`, as tinyobjloader reads lines: ended by
// "\n", "\r\n" or a lone "\r", and cut at its first NUL byte (tinyobjloader reads a line as a C
// string). Moves `start` past the line's end. Reading the lines alike matters: a line this pass
// took for a vertex but tinyobjloader did not would let a face index point past its vertices.
std::string_view next_line(std::string_view text, std::size_t& start);

// Throws InputError at `where` when a word of the line (comments included) is a number whose
// exponent has more than 6 digits, such as 1e-21474836491: tinyobjloader's number reader
// overflows an int on those (found by fuzz_obj), wherever it meets one, in any statement.
void refuse_huge_exponents(std::string_view line, const std::string& path, std::size_t line_number);

// Splits one line into words separated by spaces or tabs; a word starting with '#' begins a
// comment, which ends the line.
void split_words(std::string_view line, std::vector<std::string_view>& words);

// True when the whole word is a decimal number ("1", "-0.5", "+2e-3", "nan", "inf"); stores it.
bool parse_number(std::string_view word, double& value);

// Checks every v, vt, vn and f line of an OBJ file's text and collects its mtllib and usemtl
// lines. Throws InputError("path:LINE", ...) at the first malformed line or face index out of
// range. `path` is only used in messages.
ObjTextSummary check_obj_text(std::string_view text, const std::string& path);

}  // namespace freezeray::obj_detail
