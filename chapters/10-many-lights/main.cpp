// ch10: the renderer of chapters 01 to 10.
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
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch10", 10);
    freezeray::register_chapter01(registry);
    freezeray::register_chapter02(registry);
    freezeray::register_chapter03(registry);
    freezeray::register_chapter04(registry);
    freezeray::register_chapter05(registry);
    freezeray::register_chapter06(registry);
    freezeray::register_chapter07(registry);
    freezeray::register_chapter08(registry);
    freezeray::register_chapter09(registry);
    freezeray::register_chapter10(registry);
    return freezeray::run_command_line(argc, argv, registry);
}
