#include "cl/programs.h"

#include <regex>
#include <set>
#include <sstream>

#include "cl/embedded_kernels.h"
#include "common/errors.h"
#include "common/models.h"

namespace brdfbake {

namespace {

const char* embedded(const std::string& path) {
  for (const auto& f : kEmbeddedKernelSources)
    if (path == f.path) return f.text;
  throw Error(kExitSoftware, "internal: OpenCL source " + path + " is not embedded (CMakeLists.txt globs kernels/)");
}

// Appends kernels/`rel` with each #include "X" replaced by kernels/X (recursively), each file once
// per pass: the headers' guards would skip a second copy anyway (kernels/brdf/compat.h "Passes"),
// and leaving it out keeps the integrators' program at 4,050 lines instead of 44,000. The
// pass is followed from the #define / #undef BRDF_SECOND_PASS lines (integrate/lanes.h); should
// this ever leave out a file the compiler needs, the build fails naming the missing function.
// The nesting is bounded: the include graph has no loops (tests/check_kernel_headers.py).
struct Joiner {
  std::string src;
  std::set<std::pair<bool, std::string>> seen;  // (second pass, file)
  bool second = false;

  void append(const std::string& rel) {
    if (!seen.insert({second, rel}).second) return;
    const std::string path = "kernels/" + rel;
    src += "#line 1 \"" + path + "\"\n";
    std::istringstream in(embedded(path));
    std::string line;
    static const std::regex include(R"re(^\s*#\s*include\s+"([^"]+)".*)re");
    static const std::regex pass(R"re(^\s*#\s*(define|undef)\s+BRDF_SECOND_PASS\b.*)re");
    std::smatch m;
    for (int n = 1; std::getline(in, line); ++n) {
      if (line.find("BRDF_SECOND_PASS") != std::string::npos && std::regex_match(line, m, pass))
        second = m[1] == "define";
      if (line.find("include") == std::string::npos || !std::regex_match(line, m, include)) {
        src += line;
        src += '\n';
        continue;
      }
      append(m[1].str());
      src += "#line " + std::to_string(n + 1) + " \"" + path + "\"\n";
    }
  }
};

const char* topFile(ProgramKey::Kind kind) {
  switch (kind) {
    case ProgramKey::Volume: return "brdf3d.cl";
    case ProgramKey::Dielectric: return "dielectric.cl";
    case ProgramKey::Integrators: break;
  }
  return "bake.cl";
}

}  // namespace

std::string programName(const ProgramKey& key) {
  if (key.isShared()) return "every pair (the shared program)";
  std::string name = ndfNames()[key.ndf] + " + " + gafNames()[key.gaf];
  if (key.kind == ProgramKey::Volume) name += " (3D tables)";
  if (key.kind == ProgramKey::Dielectric) name += " (rough dielectric)";
  return name;
}

const char* const kProgramBuildOptions = "-cl-std=CL1.2 -w";

bool programKeyNamed(const std::string& name, ProgramKey* key) {
  std::vector<ProgramKey> keys = {ProgramKey::shared()};
  for (int ndf = 0; ndf < static_cast<int>(ndfNames().size()); ++ndf)
    for (int gaf = 0; gaf < static_cast<int>(gafNames().size()); ++gaf)
      if (pairSupported(ndf, gaf))
        for (ProgramKey::Kind k : {ProgramKey::Integrators, ProgramKey::Volume, ProgramKey::Dielectric})
          keys.push_back(ProgramKey{k, ndf, gaf});
  for (const ProgramKey& k : keys)
    if (programName(k) == name) {
      *key = k;
      return true;
    }
  return false;
}

std::string programSource(const ProgramKey& key) {
  std::string src = "/* brdfbake prelude: " + programName(key) + " */\n";
  if (key.isShared()) {
    src += "#define BRDF_NDF sel_ndf\n#define BRDF_GAF sel_gaf\n";
  } else {
    src += "#define BRDF_NDF " + std::to_string(key.ndf) + "\n#define BRDF_GAF " + std::to_string(key.gaf) + "\n";
  }
  // the models evaluated at points (3D tables, glass) ask for double where the device has it
  if (key.kind != ProgramKey::Integrators) src += "#define BRDF_DEVICE_DOUBLE 1\n";
  Joiner j;
  j.append(topFile(key.kind));
  return src + j.src;
}

}  // namespace brdfbake
