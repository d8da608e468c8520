// ch06: the renderer of chapters 01 to 06.
#include "freezeray/ch06/register_chapter06.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch06", 6);
    freezeray::register_chapter06(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
