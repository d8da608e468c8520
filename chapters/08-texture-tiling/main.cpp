// ch08: the renderer of chapters 01 to 08.
#include "freezeray/ch08/register_chapter08.hpp"
#include "freezeray/cli.hpp"

int main(int argc, char** argv) {
    freezeray::Registry registry("ch08", 8);
    freezeray::register_chapter08(registry);  // and every chapter before it
    return freezeray::run_command_line(argc, argv, registry);
}
