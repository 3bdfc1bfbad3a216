// Errors thrown by brdfbake (the library and the command line) and the sysexits-style exit code
// each maps to.
// The command line catches them once, in main(), prints the message and exits with the code.
#pragma once
#include <stdexcept>
#include <string>

namespace brdfbake {

// Exit codes from BSD sysexits.h (values are fixed by that convention).
enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 64,        // EX_USAGE: bad command line
  kExitDataErr = 65,      // EX_DATAERR: input data incorrect (e.g. a model diverges on this grid)
  kExitNoInput = 66,      // EX_NOINPUT: input file missing or unreadable
  kExitUnavailable = 69,  // EX_UNAVAILABLE: no OpenCL platform/device
  kExitSoftware = 70,     // EX_SOFTWARE: internal error (kernel build failure, NaN in output)
  kExitCantCreat = 73,    // EX_CANTCREAT: output cannot be created
  kExitIoErr = 74,        // EX_IOERR: I/O error while writing (disk full, quota, no inodes)
  kExitTempFail = 75,     // EX_TEMPFAIL: try again later (another bake holds the output directory)
};

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

}  // namespace brdfbake
