// brdfbake: bakes BRDF lookup tables (split-sum, albedo, average albedo, k_p) with OpenCL.
// Pipeline: command line -> plan of tables -> OpenCL jobs -> EXR files and a report.
// Errors are exceptions inside, caught here once and mapped to sysexits-style exit codes.
#include <CL/opencl.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <exception>
#include <iostream>

#include "bake/bake.h"
#include "brdfbake/brdfbake.h"
#include "formats/output_set.h"
#include "tables/volume.h"
#include "shader/shader_gen.h"
#include "cl/device.h"
#include "cl/driver_guard.h"
#include "cli/args.h"
#include "cli/console.h"
#include "cli/commands.h"
#include "common/errors.h"
#include "formats/exr/table_file.h"
#include "formats/readers/table_reader.h"
#include "plan/plan.h"
#include "report/convergence.h"
#include "report/energy.h"
#include "report/stress.h"
#include "render/render.h"
#include "report/verify.h"
#include "version.h"

namespace {
using namespace brdfbake;

// One command, run; its exit status. Errors are thrown (Error, cl::Error) and caught in main.
int runCommand(Command& cmd) {
  {
    switch (cmd.kind) {
      case Command::Kind::Help:
        std::cout << (cmd.helpFor.empty()           ? overviewHelp()
                      : cmd.helpFor == "--markdown" ? markdownHelp()
                                                    : commandHelp(cmd.helpFor));
        return kExitOk;
      case Command::Kind::Completion:
        std::cout << bashCompletion();
        return kExitOk;
      case Command::Kind::Version:
        std::cout << "brdfbake " << BRDFBAKE_VERSION << " (git " << BRDFBAKE_GIT_REV << ")\n";
        return kExitOk;
      case Command::Kind::Devices:
        if (!cmd.bake.cacheDir.empty()) usePoclCache(cmd.bake.cacheDir);
        if (!cmd.file.empty())
          std::cout << preparePrograms(cmd.file, cmd.bake.device);
        else
          std::cout << describeDevices();
        return kExitOk;
      case Command::Kind::Info: {
        const TableFile file = readTableFile(cmd.file);  // any format the baker writes
        std::cout << describeTableFile(file);
        std::cout << energyWarnings(file.table);
        return kExitOk;
      }
      case Command::Kind::ScenePlan:
        return runScenePlan(cmd.scene);
      case Command::Kind::SceneBake: {
        if (!cmd.scene.cacheDir.empty()) usePoclCache(cmd.scene.cacheDir);
        std::shared_ptr<ConsoleObserver> console = consoleObserver(cmd.timings, cmd.quiet, cmd.progress);
        cmd.scene.observer = console;
        const int code = runSceneBake(cmd.scene);
        if (console) console->finish();
        return code;
      }
      case Command::Kind::Shader: {
        if (!cmd.file.empty()) {  // before any table is read
          checkReplaceableFile(cmd.file, "-o");
          checkNotAnInput(cmd.file, cmd.files, "-o");
        }
        std::string code = shaderForFiles(cmd.files, cmd.hlsl ? ShaderLang::Hlsl : ShaderLang::Glsl);
        if (cmd.file.empty())
          std::cout << code;
        else
          writeTextFile(cmd.file, code);
        return kExitOk;
      }
      case Command::Kind::Sample:
        std::cout << sampleReport(cmd.file, cmd.at);
        return kExitOk;
      case Command::Kind::Energy: {
        if (!cmd.bake.cacheDir.empty()) usePoclCache(cmd.bake.cacheDir);
        std::vector<EnergyResult> res = checkEnergy(cmd.bake, cmd.energy);
        // the gate stays a fraction of a second; its page, with a GL render per pair, on request
        std::cout << formatEnergy(res) << (cmd.outputGiven ? writeEnergyPage(cmd.bake, res) : std::string());
        for (const auto& r : res)
          if (r.violates) return 1;  // a build gates on this
        return kExitOk;
      }
      case Command::Kind::Verify: {
        if (!cmd.bake.cacheDir.empty()) usePoclCache(cmd.bake.cacheDir);
        std::string pageLine;
        std::vector<VerifyResult> res = runVerify(cmd.bake, &pageLine);
        bool ok = true;
        for (const auto& r : res) {
          std::cout << r.summary();
          ok = ok && r.pass();
        }
        std::cout << pageLine;
        return ok ? kExitOk : 1;
      }
      case Command::Kind::Stress: {
        if (!cmd.bake.cacheDir.empty()) usePoclCache(cmd.bake.cacheDir);
        std::string pageLine;
        std::vector<StressPoint> pts = runStress(cmd.bake, &pageLine);
        std::cout << formatStress(pts) << pageLine;
        for (const auto& p : pts)
          if (!p.pass()) return 1;
        return kExitOk;
      }
      case Command::Kind::Convergence: {
        if (!cmd.bake.cacheDir.empty()) usePoclCache(cmd.bake.cacheDir);
        std::string pageLine;
        ConvergenceResult res = runConvergence(cmd.bake, cmd.ladder, &pageLine);
        std::cout << formatConvergence(res) << pageLine;
        return kExitOk;
      }
      case Command::Kind::Render:
        if (!cmd.render.cacheDir.empty()) usePoclCache(cmd.render.cacheDir);
        return runRender(cmd.render);
      case Command::Kind::Bake: {
        if (cmd.dryRun) {
          std::cout << formatPlan(makePlan(cmd.bake));
          return kExitOk;
        }
        if (!cmd.bake.cacheDir.empty()) usePoclCache(cmd.bake.cacheDir);
        std::shared_ptr<ConsoleObserver> console = consoleObserver(cmd.timings, cmd.quiet, cmd.progress);
        cmd.bake.observer = console;
        const std::string report = formatReport(bakeToDirectory(cmd.bake));
        if (console) console->finish();
        std::cout << report;
        return kExitOk;
      }
    }
  }
  return kExitSoftware;
}

// Standard output must have taken every byte: a full disk or a closed pipe at the end of a
// command that printed its result is an I/O error (74), not success.
int checkedStdout(int code) {
  std::cout.flush();
  const bool failed = std::cout.fail() || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (!failed) return code;
  const int err = errno;
  std::cerr << "brdfbake: cannot write standard output"
            << (err ? std::string(": ") + std::strerror(err) : std::string()) << "\n";
  return code == kExitOk ? kExitIoErr : code;
}

}  // namespace

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) makes writes past it fail with EFBIG, which the writers report
  // and clean up after (74), instead of a SIGXFSZ that kills the process mid-write.
  std::signal(SIGXFSZ, SIG_IGN);
  // The OpenCL driver's crashes and exits while it builds kernels, said as its failure (70, 74).
  installDriverGuards();
  try {
    Command cmd = parseArgs(std::vector<std::string>(argv + 1, argv + argc));
    return checkedStdout(runCommand(cmd));
  } catch (const Error& e) {
    std::cerr << "brdfbake: " << e.what() << "\n";
    return e.code();
  } catch (const cl::Error& e) {
    std::cerr << "brdfbake: OpenCL error " << e.err() << " in " << e.what() << "\n";
    return kExitSoftware;
  } catch (const std::exception& e) {
    std::cerr << "brdfbake: internal error: " << e.what() << "\n";
    return kExitSoftware;
  }
  return kExitSoftware;
}
