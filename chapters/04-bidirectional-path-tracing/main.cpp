// ch04: the renderer of chapters 01 to 04.
#include "freezeray/ch04/register_chapter04.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch04", 4);
    freezeray::register_chapter04(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
