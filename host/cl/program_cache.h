// OpenCL program binaries kept between runs, so that a bake loads its programs instead of
// compiling them. On PoCL a program costs a front-end compile at clBuildProgram and a work-group
// function per kernel at its first launch; the binary taken after both holds them, and loading it
// skips both (docs/performance.md has the figures).
//
// An entry is keyed by everything the binary depends on: the platform and device (name, version,
// driver version), the build options and the program's full source. The entry stores that identity
// and is used only when it matches byte for byte and its checksum holds: a stale entry (other
// sources, another driver) or a foreign one (another device) is never loaded.
//
// BRDFBAKE_PROGRAM_CACHE=off (or empty) turns the cache off: every program is compiled from source.
// Where entries live, searched in this order:
//  1. the user's cache, which a source build fills: $BRDFBAKE_PROGRAM_CACHE; else, when PoCL's
//     cache is set (POCL_CACHE_DIR, --cache-dir DIR), DIR/brdfbake-programs; else
//     $XDG_CACHE_HOME/brdfbake/programs or ~/.cache/brdfbake/programs;
//  2. the programs prepared at build time (`brdfbake devices --prepare DIR`, run by the build into
//     build/programs, installed as share/brdfbake/programs), read only; $BRDFBAKE_PREPARED_PROGRAMS
//     names another directory instead, or none (off).
#pragma once
#include <CL/opencl.hpp>
#include <optional>
#include <string>
#include <vector>

namespace brdfbake {

using ProgramBinary = std::vector<unsigned char>;

// The identity of a program on a device: what an entry must match to be loaded.
std::string programIdentity(const cl::Device& device, const std::string& name, const std::string& options,
                            const std::string& source);

// The directories searched, the writable one first (it may not exist yet).
std::vector<std::string> programCacheDirs();
// The directory a source build's binary is stored in ("" when the cache is off).
std::string programCacheWriteDir();
bool programCacheOff();

// The binary of the entry matching `identity`, in the first directory that has one; `where` gets
// its path.
std::optional<ProgramBinary> loadProgram(const std::string& identity, std::string* where = nullptr);
// Stores a binary under `identity` in `dir` (default: programCacheWriteDir()), atomically (a
// temporary renamed into place). Returns "" or why it was not stored; a cache that cannot be
// written costs the next run a build, never a failure.
std::string storeProgram(const std::string& identity, const ProgramBinary& binary, std::string dir = "");

// The entries in `dir` made for `device`: the names of the programs that a bake of this build
// loads (same sources and options), and how many others there are (stale: other sources, from
// another version or build; never loaded).
struct PreparedPrograms {
  std::vector<std::string> ready;
  int stale = 0;
};
PreparedPrograms preparedPrograms(const std::string& dir, const cl::Device& device);

}  // namespace brdfbake
