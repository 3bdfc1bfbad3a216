#include "cl/programs.h"

#include <cctype>
#include <cstring>
#include <set>

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

// The directive a line holds: "#", spaces, `word`, spaces; where the rest of the line starts, or
// npos. Parsed by hand, not by std::regex: joining the integrators' program (the first call in a
// process) takes 1.5 ms with the regexes, 1.4 ms without, 0.7 ms with the string reserved.
size_t directive(const std::string& line, const char* word) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return std::string::npos;
  i = line.find_first_not_of(" \t", i + 1);
  const size_t n = std::strlen(word);
  if (i == std::string::npos || line.compare(i, n, word) != 0) return std::string::npos;
  i += n;
  if (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '"') return std::string::npos;
  i = line.find_first_not_of(" \t", i);
  return i == std::string::npos ? line.size() : i;
}
// The file a line includes (#include "X"), or "".
std::string includedFile(const std::string& line) {
  size_t i = directive(line, "include");
  if (i == std::string::npos || i >= line.size() || line[i] != '"') return "";
  size_t end = line.find('"', i + 1);
  return end == std::string::npos ? "" : line.substr(i + 1, end - i - 1);
}
// +1 for #define BRDF_SECOND_PASS, -1 for #undef, 0 otherwise.
int passDirective(const std::string& line) {
  for (int sign : {1, -1}) {
    size_t i = directive(line, sign > 0 ? "define" : "undef");
    const char* name = "BRDF_SECOND_PASS";
    const size_t n = std::strlen(name);
    if (i == std::string::npos || line.compare(i, n, name) != 0) continue;
    const char next = i + n < line.size() ? line[i + n] : ' ';
    if (!std::isalnum(static_cast<unsigned char>(next)) && next != '_') return sign;
  }
  return 0;
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
    const char* text = embedded(path);
    const size_t size = std::strlen(text);
    std::string line;
    int n = 0;
    for (size_t at = 0; at < size;) {
      const char* nl = static_cast<const char*>(std::memchr(text + at, '\n', size - at));
      const size_t end = nl ? static_cast<size_t>(nl - text) : size;
      size_t first = at;
      while (first < end && (text[first] == ' ' || text[first] == '\t')) ++first;
      ++n;
      if (first == end || text[first] != '#') {  // not a directive: the line as it is
        src.append(text + at, end - at);
        src += '\n';
        at = end + 1;
        continue;
      }
      line.assign(text + at, end - at);
      at = end + 1;
      if (int d = passDirective(line)) second = d > 0;
      const std::string inc = includedFile(line);
      if (inc.empty()) {
        src += line;
        src += '\n';
        continue;
      }
      append(inc);
      src += "#line " + std::to_string(n + 1) + " \"" + path + "\"\n";
    }
  }
};

const char* topFile(ProgramKey::Kind kind) {
  switch (kind) {
    case ProgramKey::Volume:
      return "brdf3d.cl";
    case ProgramKey::Dielectric:
      return "dielectric.cl";
    case ProgramKey::Ltc:
      return "ltc.cl";
    case ProgramKey::Integrators:
      break;
  }
  return "bake.cl";
}

}  // namespace

std::string programName(const ProgramKey& key) {
  if (key.isShared()) return "every pair (the shared program)";
  std::string name = ndfNames()[key.ndf] + " + " + gafNames()[key.gaf];
  if (key.kind == ProgramKey::Volume) name += " (3D tables)";
  if (key.kind == ProgramKey::Dielectric) name += " (rough dielectric)";
  if (key.kind == ProgramKey::Ltc) name += " (LTC fits)";
  return name;
}

const char* const kProgramBuildOptions = "-cl-std=CL1.2 -w";

bool programKeyNamed(const std::string& name, ProgramKey* key) {
  std::vector<ProgramKey> keys = {ProgramKey::shared()};
  for (int ndf = 0; ndf < static_cast<int>(ndfNames().size()); ++ndf)
    for (int gaf = 0; gaf < static_cast<int>(gafNames().size()); ++gaf)
      if (pairSupported(ndf, gaf))
        for (ProgramKey::Kind k : {ProgramKey::Integrators, ProgramKey::Volume, ProgramKey::Dielectric, ProgramKey::Ltc})
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
  // the models evaluated at points (3D tables, glass) ask for double where the device has it; the
  // LTC fits run in float (their distance's estimate error, ~1e-5, is far above float's rounding)
  if (key.kind == ProgramKey::Volume || key.kind == ProgramKey::Dielectric) src += "#define BRDF_DEVICE_DOUBLE 1\n";
  Joiner j;
  size_t all = 0;  // room for every file once per pass: growing the 0.5 MB string page-faults 0.7 ms
  for (const auto& f : kEmbeddedKernelSources) all += std::strlen(f.text);
  j.src.reserve(2 * all);
  j.append(topFile(key.kind));
  return src + j.src;
}

}  // namespace brdfbake
