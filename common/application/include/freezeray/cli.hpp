// The command line shared by every chapter's renderer: `render` and `info` (see README.md).
#pragma once

#include "freezeray/registry.hpp"

namespace freezeray {

// Parses argv, runs the command and returns the process exit status. Bad input gives a message
// on standard error that names what and where, exit status 1, and no output file.
int run_command_line(int argc, char** argv, const Registry& registry);

}  // namespace freezeray
