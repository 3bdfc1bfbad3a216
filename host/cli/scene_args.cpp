#include "cli/scene_args.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

#include "cli/commands.h"
#include "common/errors.h"

namespace brdfbake {

bool parseSceneCommand(const std::vector<std::string>& args, Command& cmd) {
  if (args.empty()) return false;
  bool plan = args[0] == "plan";
  // bake SCENE: the word after bake is a file, not an option
  bool bake = args[0] == "bake" && args.size() > 1 && !args[1].empty() && args[1][0] != '-';
  if (!plan && !bake) return false;
  if (args.size() < 2 || args[1].empty() || args[1][0] == '-')
    throw Error(kExitUsage,
                "plan: expected a scene file (.toml manifest, .gltf or .glb): brdfbake plan SCENE [options]");
  SceneOptions o;
  o.file = args[1];
  std::vector<std::string> seen;
  for (size_t i = 2; i < args.size(); ++i) {
    const std::string& opt = args[i];
    if (!takesOption(plan ? "plan" : "bake SCENE", opt)) refuseOption(plan ? "plan" : "bake SCENE", opt);
    if (std::find(seen.begin(), seen.end(), opt) != seen.end())
      throw Error(kExitUsage, opt + " given twice; give it once");
    seen.push_back(opt);
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size() || (args[i + 1].size() > 1 && args[i + 1][0] == '-'))
        throw Error(kExitUsage, opt + ": missing value");
      return args[++i];
    };
    if (opt == "-o" || opt == "--output") {
      o.outDir = value();
      if (o.outDir.empty()) throw Error(kExitUsage, opt + ": empty directory name");
    } else if (opt == "--shard") {
      const std::string& v = value();
      char* end = nullptr;
      errno = 0;
      long a = std::strtol(v.c_str(), &end, 10);
      long b = (end && *end == '/') ? std::strtol(end + 1, &end, 10) : 0;
      if (v.empty() || !end || *end != '\0' || errno != 0 || b < 1 || b > 4096 || a < 1 || a > b)
        throw Error(kExitUsage, "--shard must be I/N with 1 <= I <= N <= 4096 (part I of N), got '" + v + "'");
      o.shard = static_cast<int>(a);
      o.shards = static_cast<int>(b);
    } else if (opt == "--list") {
      o.list = true;
    } else if (opt == "--no-wait") {
      o.noWait = true;
    } else if (opt == "--progress") {
      cmd.progress = true;
    } else if (opt == "--timings" || opt == "--quiet") {
      (opt == "--timings" ? cmd.timings : cmd.quiet) = true;
    } else if (opt == "--force") {
      o.force = true;
    } else if (opt == "--prune") {
      o.prune = true;
    } else if (opt == "--stamp") {
      o.stamp = value();
    } else if (opt == "--device") {
      o.device = value();
    } else if (opt == "--cache-dir") {
      o.cacheDir = value();
    } else {
      throw Error(kExitSoftware, "internal: " + opt + " is in the option table (cli/option_table.cpp) but not parsed");
    }
  }
  cmd.kind = plan ? Command::Kind::ScenePlan : Command::Kind::SceneBake;
  cmd.scene = o;
  return true;
}

}  // namespace brdfbake
