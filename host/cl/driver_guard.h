// The OpenCL driver's own failures while it builds kernels, said in brdfbake's words.
//
// PoCL writes into its kernel cache ($POCL_CACHE_DIR, --cache-dir) while it builds a program and
// links each kernel at its first launch, and fails there in ways no error code reports:
//  - the directory removed during a build: PoCL aborts (SIGABRT, "Final linking of kernel ...
//    failed"), or the build fails with a log that holds no compiler diagnostic;
//  - the directory's file system full: LLVM prints "LLVM ERROR: IO failure on output stream" and
//    calls exit(1), the status brdfbake keeps for a failed check.
// A build needs about 2 MB there (the default set: fails with 1.6 MB free, builds with 2 MB).
#pragma once
#include <string>

#include "brdfbake/error.h"

namespace brdfbake {

// Free bytes below which a source build is refused before the driver starts (74): 16 MiB, 8 times
// the default set's measured need, so that two programs built at once fit.
constexpr unsigned long long kDriverCacheMinFree = 16ull << 20;

// Throws Error(kExitIoErr) naming `dir` when its file system (or that of the nearest existing
// ancestor it would be created under) has less than kDriverCacheMinFree bytes free.
void checkDriverCacheSpace(const std::string& dir);

// The hint added to a build failure whose log holds no compiler diagnostic ("" when the log has
// one): where the driver writes, and what to look at.
std::string driverCacheHint(const std::string& log, const std::string& dir);

// The exit status of a build that failed with `log`: 73 when the log holds no compiler diagnostic
// and the cache directory is gone or cannot be written (removed during the build), else 70.
ExitCode driverFailureCode(const std::string& log, const std::string& dir);

// Marks the driver at work for its scope (nested and concurrent scopes count). While one is open, a
// crash (SIGABRT, SIGSEGV, SIGBUS) or an exit() from inside the driver is reported as the driver's
// failure in `dir`, with exit status 73 (a crash: the directory changed underneath) or 74 (an exit:
// LLVM's I/O failure), once
// installDriverGuards() has run.
class DriverWork {
 public:
  explicit DriverWork(const std::string& dir);
  ~DriverWork();
  DriverWork(const DriverWork&) = delete;
  DriverWork& operator=(const DriverWork&) = delete;
};

// Installs the handlers DriverWork relies on (the command-line program calls it first; a library
// user may, or keep its own). Signals outside a DriverWork scope keep their default action.
void installDriverGuards();

}  // namespace brdfbake
