// The complete renderer's registry: every chapter of the course registered, in order. The
// executable `freezeray` and the test suite both use it, so neither names the last chapter.
#pragma once

#include "freezeray/registry.hpp"

#include <string>

namespace freezeray {

// The last chapter of the course that this build contains.
int last_chapter();

// A registry for `program` with chapters 01 to last_chapter() registered.
Registry make_complete_registry(const std::string& program);

}  // namespace freezeray
