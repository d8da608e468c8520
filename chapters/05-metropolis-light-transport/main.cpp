// ch05: the renderer of chapters 01 to 05.
#include "freezeray/ch05/register_chapter05.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch05", 5);
    freezeray::register_chapter05(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
