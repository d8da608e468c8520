// Errors caused by the user's input: a scene, a mesh, an image, an option. Each names what was
// wrong and where, so the command line can print it and exit non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace freezeray {

class InputError : public std::runtime_error {
public:
    // where: "file.obj:12", "scene.json: /meshes/0/file", "--spp"; what: the problem in words.
    InputError(const std::string& where, const std::string& what)
        : std::runtime_error(where.empty() ? what : where + ": " + what), where_(where), what_(what) {}

    const std::string& where() const { return where_; }
    const std::string& problem() const { return what_; }

private:
    std::string where_;
    std::string what_;
};

// Thrown by the stub that replaces an exercise region in a student copy (see tests/grading/).
// Defined out of line (error.cpp), with a constructor from the stub's string literal: a stub may
// sit in code compiled for one instruction set (chapter 07's AVX-512 kernel), and the inline
// code such a file emits could be picked by the linker for the whole program.
class ExerciseNotImplemented : public std::logic_error {
public:
    explicit ExerciseNotImplemented(const char* exercise);
    explicit ExerciseNotImplemented(const std::string& exercise);
    ~ExerciseNotImplemented() override;
};

}  // namespace freezeray
