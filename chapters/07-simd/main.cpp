// ch07: the renderer of chapters 01 to 07.
#include "freezeray/ch07/register_chapter07.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch07", 7);
    freezeray::register_chapter07(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
