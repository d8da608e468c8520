// The complete renderer's registry: every chapter of the course registered, in order. The
// executable `freezeray` and the test suite both use it, so neither names the last chapter.
#pragma once

#include "freezeray/registry.hpp"

#include <string>

namespace freezeray {

// The last chapter of the course that this build contains.
int last_chapter();

// Whether chapter `number` is written and registered: every chapter up to the last.
bool chapter_is_written(int number);

// A registry for `program` with every written chapter up to last_chapter() registered.
Registry make_complete_registry(const std::string& program);

}  // namespace freezeray
