// The complete renderer's registry. A new chapter adds its register call here (and its
// freezeray_add_chapter block in CMakeLists.txt); nothing else names the last chapter.
#include "freezeray/complete_renderer.hpp"

#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/ch03/register_chapter03.hpp"
#include "freezeray/ch04/register_chapter04.hpp"
#include "freezeray/ch05/register_chapter05.hpp"
#include "freezeray/ch06/register_chapter06.hpp"
#include "freezeray/ch07/register_chapter07.hpp"
#include "freezeray/ch08/register_chapter08.hpp"
#include "freezeray/ch09/register_chapter09.hpp"
#include "freezeray/ch10/register_chapter10.hpp"

namespace freezeray {

namespace {

// Every written chapter's number and register function, in the order of the course.
struct Chapter {
    int number;
    void (*register_chapter)(Registry&);
};
const Chapter chapters[] = {
    {1, register_chapter01}, {2, register_chapter02}, {3, register_chapter03}, {4, register_chapter04},
    {5, register_chapter05}, {6, register_chapter06}, {7, register_chapter07},
    {8, register_chapter08}, {9, register_chapter09}, {10, register_chapter10},
};

}  // namespace

int last_chapter() { return std::end(chapters)[-1].number; }

bool chapter_is_written(int number) {
    for (const Chapter& c : chapters)
        if (c.number == number) return true;
    return false;
}

Registry make_complete_registry(const std::string& program) {
    Registry registry(program, last_chapter());
    for (const Chapter& c : chapters) c.register_chapter(registry);
    return registry;
}

}  // namespace freezeray
