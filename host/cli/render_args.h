// `brdfbake render [options]`, parsed apart from the table options.
#pragma once
#include <string>
#include <vector>

#include "cli/args.h"

namespace brdfbake {

// True when `args` is the render command, with `cmd` filled in; false otherwise (cmd untouched).
// Throws Error(kExitUsage) naming the option and its accepted values.
bool parseRenderCommand(const std::vector<std::string>& args, Command& cmd);

}  // namespace brdfbake
