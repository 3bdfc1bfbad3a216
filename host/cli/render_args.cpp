// `brdfbake render` options (cli/render_args.h).
#include "cli/render_args.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

#include "cli/commands.h"
#include "common/errors.h"

namespace brdfbake {

namespace {
int integer(const std::string& opt, const std::string& v, const std::string& range) {
  char* end = nullptr;
  errno = 0;
  long n = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || errno != 0 || n < -100000 || n > 100000)
    throw Error(kExitUsage, opt + ": expected an integer, " + range + ", got '" + v + "'");
  return static_cast<int>(n);
}
}  // namespace

bool parseRenderCommand(const std::vector<std::string>& args, Command& cmd) {
  if (args.empty() || args[0] != "render") return false;
  RenderOptions o;
  std::vector<std::string> seen;
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& opt = args[i];
    if (opt.empty() || opt[0] != '-') throw Error(kExitUsage, "render: unexpected argument '" + opt + "'");
    if (!takesOption("render", opt)) refuseOption("render", opt);
    const std::string canonical = opt == "-o" ? "--output" : opt;
    if (std::find(seen.begin(), seen.end(), canonical) != seen.end())
      throw Error(kExitUsage, opt + " given twice; give it once");
    seen.push_back(canonical);
    if (opt == "--no-wait") {
      o.noWait = true;
      continue;
    }
    if (i + 1 >= args.size() ||
        (args[i + 1].size() > 1 && args[i + 1][0] == '-' && !std::isdigit(static_cast<unsigned char>(args[i + 1][1]))))
      throw Error(kExitUsage, opt + ": missing value");
    const std::string& v = args[++i];
    if (canonical == "--output") {
      if (v.empty()) throw Error(kExitUsage, opt + ": empty directory name");
      o.outDir = v;
    } else if (opt == "--cell") {
      o.cell = integer(opt, v, "16..256 (pixels per sphere)");
    } else if (opt == "--columns") {
      o.columns = integer(opt, v, "2..33 (roughness steps)");
    } else if (opt == "--rows") {
      o.rows = splitCommas(v);
    } else if (opt == "--light") {
      if (v != "furnace" && v != "quad")
        throw Error(kExitUsage, "--light: unknown light '" + v + "'" + didYouMean(v, {"furnace", "quad"}) +
                                    "; valid: furnace, quad");
      o.light = v;
    } else if (opt == "--ndf" || opt == "--gaf") {
      if (v.find(',') != std::string::npos)
        throw Error(kExitUsage, opt + ": render shades one pair; give one name, got '" + v + "'");
      (opt == "--ndf" ? o.ndf : o.gaf) = v;
    } else if (opt == "--device") {
      o.device = v;
    } else if (opt == "--cache-dir") {
      o.cacheDir = v;
    }
  }
  cmd.kind = Command::Kind::Render;
  cmd.render = o;
  return true;
}

}  // namespace brdfbake
