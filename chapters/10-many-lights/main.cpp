// ch10: the renderer of chapters 01 to 10.
#include "freezeray/ch10/register_chapter10.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch10", 10);
    freezeray::register_chapter10(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
