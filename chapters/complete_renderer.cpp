// The complete renderer's registry. The last chapter's register function registers every chapter
// before it; CMake names that chapter (FREEZERAY_LAST_CHAPTER, from the last
// freezeray_add_chapter block), so a new chapter touches nothing here.
#include "freezeray/complete_renderer.hpp"

#include FREEZERAY_LAST_CHAPTER_HEADER

namespace freezeray {

int last_chapter() { return FREEZERAY_LAST_CHAPTER; }

// Every chapter up to the last is written: each one's register function calls its predecessor's.
bool chapter_is_written(int number) { return number >= 1 && number <= last_chapter(); }

Registry make_complete_registry(const std::string& program) {
    Registry registry(program, last_chapter());
    FREEZERAY_LAST_CHAPTER_REGISTER(registry);
    return registry;
}

}  // namespace freezeray
