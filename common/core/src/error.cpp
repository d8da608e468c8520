// The exception of an exercise's stub (see error.hpp for why it is defined here).
#include "freezeray/error.hpp"

namespace freezeray {

ExerciseNotImplemented::ExerciseNotImplemented(const std::string& exercise)
    : std::logic_error("exercise " + exercise + " is not implemented yet (see the chapter's book page)") {}

ExerciseNotImplemented::ExerciseNotImplemented(const char* exercise) : ExerciseNotImplemented(std::string(exercise)) {}

ExerciseNotImplemented::~ExerciseNotImplemented() = default;

}  // namespace freezeray
