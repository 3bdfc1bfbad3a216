// `brdfbake plan SCENE ...` and `brdfbake bake SCENE ...`, parsed apart from the table options.
#pragma once
#include <string>
#include <vector>

#include "cli/args.h"

namespace brdfbake {

// True when `args` is a scene command (plan ..., or bake followed by a file argument), with `cmd`
// filled in; false otherwise (cmd untouched). Throws Error(kExitUsage) naming the option.
bool parseSceneCommand(const std::vector<std::string>& args, Command& cmd);

}  // namespace brdfbake
