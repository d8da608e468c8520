// ch01: the renderer of chapter 01.
#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch01", 1);
    freezeray::register_chapter01(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
