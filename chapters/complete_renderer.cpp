// The complete renderer's registry. A new chapter adds its register call here (and its
// freezeray_add_chapter block in CMakeLists.txt); nothing else names the last chapter.
#include "freezeray/complete_renderer.hpp"

#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/ch03/register_chapter03.hpp"
#include "freezeray/ch04/register_chapter04.hpp"
#include "freezeray/ch05/register_chapter05.hpp"
#include "freezeray/ch06/register_chapter06.hpp"

namespace freezeray {

namespace {

// Every chapter's register function, in the order of the course.
void (*const chapters[])(Registry&) = {
    register_chapter01, register_chapter02, register_chapter03, register_chapter04, register_chapter05, register_chapter06,
};

}  // namespace

int last_chapter() { return static_cast<int>(std::size(chapters)); }

Registry make_complete_registry(const std::string& program) {
    Registry registry(program, last_chapter());
    for (auto register_chapter : chapters) register_chapter(registry);
    return registry;
}

}  // namespace freezeray
