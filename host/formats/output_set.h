// A set of table files that lands whole or not at all: every file is written to a temporary next to
// its target and synced, then all are renamed together; any failure, or SIGINT/SIGTERM/SIGHUP at
// any point before the renames, leaves the output directory exactly as it was (no temporaries, no
// directories created, earlier outputs untouched).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "formats/exr/table_file.h"

namespace brdfbake {

struct OutputFile {
  std::string path;
  const TableImage* image = nullptr;
  bool half = false;
  // When set, writes (and syncs) the temporary it is given itself, instead of `image`: tables too
  // large to hold whole (3D tables, streamed slab by slab) and other formats. It throws Error, and
  // the set then removes every temporary as for any other failure.
  std::function<void(const std::string& tmp)> write;
  // The most bytes the file can take, checked against the free space before anything is written;
  // 0: from `image` (tableExrBytesBound), or unknown (a writer that checks its own, brdf3d).
  uint64_t bytesBound = 0;
};

// The bytes free to an unprivileged writer on the file system that holds `dir`, or its nearest
// existing ancestor (named in `where`); UINT64_MAX when none can be asked.
uint64_t freeBytesAt(const std::string& dir, std::string* where = nullptr);

// Before any work: `dir` is a directory we can write into, or can be created (mkdir -p) under the
// nearest existing ancestor. Throws Error(kExitCantCreat) naming -o otherwise. Creates nothing.
void checkOutputDir(const std::string& dir);

// From here until commitOutputs returns, SIGINT, SIGTERM and SIGHUP remove whatever this process
// has written, print "brdfbake: interrupted (SIGINT): <what>; ..." and exit 128 + the signal.
// `what` names the abandoned work, e.g. "abandoned 4 tables for out/".
void guardInterrupts(const std::string& what);

// Creates `dir` (and missing parents), writes every file to a temporary, syncs, renames them all.
// Error kExitIoErr (write failed, e.g. disk full) or kExitCantCreat (cannot create); in either case
// nothing is left behind and files that were there before are unchanged.
// Under the directory's lock (formats/commit_record.h; wait = false: Error(kExitTempFail) when another
// process holds it), after finishing what a killed bake left there.
void commitOutputs(const std::string& dir, const std::vector<OutputFile>& files, bool wait = true);

// Before any work, for a file a later writeTextFile replaces (`option` names it: "--stamp"): it
// is absent or a regular file, and its directory exists or can be created. Throws
// Error(kExitCantCreat) naming the option, the path and what is there (a FIFO, a directory...).
void checkReplaceableFile(const std::string& path, const std::string& option);

// One text file (generated shader code, a bake's stamp), written through a synced temporary and a
// rename: the file is whole or untouched. Error(kExitCantCreat) / Error(kExitIoErr) naming it.
void writeTextFile(const std::string& path, const std::string& text);
// The most files one set commits (the interrupt handler's fixed table of temporaries).
inline constexpr int kMaxFilesPerSet = 511;
// Error(kExitCantCreat) naming `option` when `path` exists and is one of `inputs` (the same file,
// by device and inode): a command never replaces what it reads.
void checkNotAnInput(const std::string& path, const std::vector<std::string>& inputs, const std::string& option);

}  // namespace brdfbake
