// ch02: the renderer of chapters 01 and 02.
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch02", 2);
    freezeray::register_chapter02(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
