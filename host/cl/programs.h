// The device programs. A program is a prelude that fixes the model pair and the precision, then
// one .cl file with the headers it includes, joined in include order (kernels/brdf/compat.h
// "Passes"): the .cl files' #include lines are the one manifest of what each program holds.
#pragma once
#include <string>
#include <tuple>

namespace brdfbake {

// Which program a kernel lives in:
//  - Integrators (kernels/bake.cl): the hemisphere, k_p and diffuse kernels, for one pair, or for
//    every pair (shared: the pair is the kernels' sel_ndf, sel_gaf arguments);
//  - Volume (kernels/brdf3d.cl): the 3D tables, in double where the device has it;
//  - Dielectric (kernels/dielectric.cl): the rough dielectric, in double where the device has it;
//  - Ltc (kernels/ltc.cl): the LTC fits, in float.
struct ProgramKey {
  enum Kind { Integrators, Volume, Dielectric, Ltc } kind = Integrators;
  int ndf = -1, gaf = -1;  // -1, -1: the shared integrators program

  static ProgramKey shared() { return {}; }
  bool isShared() const { return ndf < 0; }
  bool operator<(const ProgramKey& o) const { return std::tie(kind, ndf, gaf) < std::tie(o.kind, o.ndf, o.gaf); }
  bool operator==(const ProgramKey& o) const { return kind == o.kind && ndf == o.ndf && gaf == o.gaf; }
};

// The program's full source: its prelude, then its .cl file with every #include "..." replaced by
// that file (paths relative to kernels/), each marked with #line for the build log.
std::string programSource(const ProgramKey& key);
// What the program is, for messages: "ggx + smith-correlated (3D tables)".
std::string programName(const ProgramKey& key);
// The program programName names, or false (a name from another version of brdfbake).
bool programKeyNamed(const std::string& name, ProgramKey* key);

// The options every program is built with. -w: without AVX-512, Clang warns about every float16
// argument ("changes the ABI"), harmless here (PoCL compiles the kernel and its library for one
// CPU) but enough to bury a real error in the build log that a failed build prints.
extern const char* const kProgramBuildOptions;

}  // namespace brdfbake
