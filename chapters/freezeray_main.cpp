// freezeray: the complete renderer, every chapter registered.
#include "freezeray/cli.hpp"
#include "freezeray/complete_renderer.hpp"

int main(int argc, char** argv) {
    const freezeray::Registry registry = freezeray::make_complete_registry("freezeray");
    return freezeray::run_command_line(argc, argv, registry);
}
