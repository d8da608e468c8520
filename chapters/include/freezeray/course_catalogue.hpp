// The course's table of contents: every capability each chapter registers, by name, including
// the chapters a renderer was built without, so that the chapter-01 renderer can say that "bdpt"
// comes in chapter 04. Chapter 01 hands it to the registry (Registry::set_catalogue).
#pragma once

#include "freezeray/registry.hpp"

#include <vector>

namespace freezeray {

// A chapter that registers a capability adds its line here; a test (tests/unit/test_registry.cpp)
// checks that the lines of chapters 01 to last_chapter() are exactly what the complete renderer
// registers, each with its chapter.
const std::vector<CatalogueEntry>& course_catalogue();

}  // namespace freezeray
