// `brdfbake completion`, `devices`, `shader`, `sample` and `info`: each takes a few arguments of
// its own, parsed apart from the table options (cli/args.cpp).
#pragma once
#include <string>
#include <vector>

#include "cli/args.h"

namespace brdfbake {

// True when `args` is one of these commands, with `cmd` filled in; false otherwise (cmd untouched).
// Throws Error(kExitUsage) naming the argument and what it accepts.
bool parseToolCommand(const std::vector<std::string>& args, Command& cmd);

}  // namespace brdfbake
