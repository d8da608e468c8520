// ch09: the renderer of chapters 01 to 09.
#include "freezeray/ch09/register_chapter09.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch09", 9);
    freezeray::register_chapter09(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
