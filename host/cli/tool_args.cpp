// The small commands' arguments (cli/tool_args.h): completion, devices, shader, sample, info.
#include "cli/tool_args.h"

#include <cerrno>
#include <cstdlib>

#include "cli/commands.h"
#include "common/errors.h"
#include "common/format.h"

namespace brdfbake {

bool parseToolCommand(const std::vector<std::string>& args, Command& cmd) {
  if (args.empty()) return false;
  if (args[0] == "completion") {
    if (args.size() != 2 || args[1] != "bash")
      throw Error(kExitUsage, "completion: expected the shell, bash (brdfbake completion bash)");
    cmd.kind = Command::Kind::Completion;
    return true;
  }
  if (args[0] == "devices") {
    // devices [--prepare DIR] [--device TEXT] [--cache-dir DIR]
    cmd.kind = Command::Kind::Devices;
    for (size_t k = 1; k < args.size(); ++k) {
      const std::string& a = args[k];
      if (a == "--prepare" || a == "--device" || a == "--cache-dir") {
        if (k + 1 >= args.size() || args[k + 1].empty())
          throw Error(kExitUsage, a + ": expected a " + (a == "--device" ? "device name" : "directory"));
        std::string& into = a == "--prepare" ? cmd.file : a == "--device" ? cmd.bake.device : cmd.bake.cacheDir;
        if (!into.empty()) throw Error(kExitUsage, a + ": give it once");
        into = args[++k];
      } else if (!a.empty() && a[0] == '-') {
        refuseOption("devices", a);
      } else {
        throw Error(kExitUsage, "devices: unexpected argument '" + a + "'");
      }
    }
    return true;
  }
  if (args[0] == "shader") {
    // shader --lang glsl|hlsl FILE... [-o OUT]
    cmd.kind = Command::Kind::Shader;
    bool langGiven = false;
    for (size_t k = 1; k < args.size(); ++k) {
      if (args[k] == "--lang") {
        if (langGiven || k + 1 >= args.size()) throw Error(kExitUsage, "--lang: give it once, glsl or hlsl");
        langGiven = true;
        const std::string& l = args[++k];
        if (l != "glsl" && l != "hlsl")
          throw Error(kExitUsage, "--lang must be glsl or hlsl, got '" + l + "'" + nearestValue("--lang", l));
        cmd.hlsl = l == "hlsl";
      } else if (args[k] == "-o" || args[k] == "--output") {
        if (!cmd.file.empty() || k + 1 >= args.size())
          throw Error(kExitUsage, args[k] + ": give one output file, once");
        cmd.file = args[++k];
      } else if (!args[k].empty() && args[k][0] == '-') {
        refuseOption("shader", args[k]);
      } else {
        cmd.files.push_back(args[k]);
      }
    }
    if (!langGiven) throw Error(kExitUsage, "shader: --lang glsl or --lang hlsl is required");
    if (cmd.files.empty())
      throw Error(kExitUsage, "shader: expected one or more table files (brdfbake shader --lang glsl FILE...)");
    return true;
  }
  if (args[0] == "sample") {
    // sample FILE --at A,B,C
    if (args.size() != 4 || args[2] != "--at")
      throw Error(kExitUsage, "sample: expected FILE.exr --at A,B,C (a brdf3d table and the point, in degrees)");
    cmd.kind = Command::Kind::Sample;
    cmd.file = args[1];
    std::vector<std::string> parts = splitCommas(args[3]);
    if (parts.size() != 3)
      throw Error(kExitUsage,
                  "--at takes three angles in degrees, A,B,C (theta_i,theta_o,phi or theta_h,theta_d,phi_d), got '" +
                      args[3] + "'");
    for (int a = 0; a < 3; ++a) {
      char* end = nullptr;
      errno = 0;
      double v = std::strtod(parts[a].c_str(), &end);
      double hi = a == 2 ? 180.0 : 90.0;
      if (parts[a].empty() || *end != '\0' || errno != 0 || !(v >= 0 && v <= hi))
        throw Error(kExitUsage, std::string("--at: angle ") + std::to_string(a + 1) + " must be in [0, " + fmtG(hi) +
                                    "] degrees, got '" + parts[a] + "'");
      cmd.at[a] = v;
    }
    return true;
  }
  if (args[0] == "info") {
    if (args.size() != 2)
      throw Error(kExitUsage, "info: expected exactly one table file (.exr, .ktx2, .dds, .png, .h, .mjs)");
    cmd.kind = Command::Kind::Info;
    cmd.file = args[1];
    return true;
  }
  return false;
}

}  // namespace brdfbake
