// Command line -> Command. Pure parsing and validation: nothing is read or written here.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "brdfbake/request.h"
#include "render/render.h"
#include "report/energy.h"
#include "tables/measures.h"
#include "scene/scene_run.h"

namespace brdfbake {

struct Command {
  enum class Kind {
    Bake,
    Energy,
    Verify,
    Stress,
    Convergence,
    Devices,
    Info,
    Sample,
    ScenePlan,
    SceneBake,
    Shader,
    Render,
    Help,
    Version,
    Completion
  } kind = Kind::Bake;
  BakeRequest bake;
  std::string file;                // for Info, Sample
  std::array<double, 3> at{};      // Sample: --at, in degrees
  SceneOptions scene;              // ScenePlan, SceneBake
  RenderOptions render;            // Render
  EnergyOptions energy;            // Energy: --coupling, --transmission
  LadderBudgets ladder;            // Convergence: --levels, --samples
  std::vector<std::string> files;  // Shader: the tables
  bool hlsl = false;               // Shader: --lang hlsl (else glsl)
  std::string helpFor;             // Help: the command whose help to print ("" = the overview)
  bool dryRun = false;             // Bake: --dry-run (print the plan and its estimated cost; compute nothing)
  bool timings = false;            // Bake, SceneBake: --timings (each stage's seconds on stderr)
  bool quiet = false;              // Bake, SceneBake: --quiet (no progress line)
  bool progress = false;           // Bake, SceneBake: --progress (progress lines also into a file or pipe)
  bool outputGiven = false;        // -o DIR given (energy writes its page only then)
};

// Throws Error(kExitUsage) with a message naming the option and the accepted values.
Command parseArgs(const std::vector<std::string>& args);

// "a,b,,c" -> {"a", "b", "", "c"}: the lists options take.
std::vector<std::string> splitCommas(const std::string& s);

}  // namespace brdfbake
