// ch03: the renderer of chapters 01 to 03.
#include "freezeray/ch03/register_chapter03.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch03", 3);
    freezeray::register_chapter03(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
