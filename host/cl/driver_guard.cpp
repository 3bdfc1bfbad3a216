#include "cl/driver_guard.h"

#include <sys/statvfs.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <algorithm>

#include "common/errors.h"

namespace brdfbake {
namespace {

std::atomic<int> g_depth{0};
std::atomic<bool> g_installed{false};
char g_dir[1024] = "";  // the cache directory of the newest scope (builds share one directory)

// The nearest existing directory at or above `dir`.
std::string existingAncestor(std::string dir) {
  while (!dir.empty()) {
    struct stat st {};
    if (::stat(dir.c_str(), &st) == 0) return dir;
    const size_t slash = dir.find_last_of('/');
    if (slash == std::string::npos) return ".";
    dir = slash == 0 ? "/" : dir.substr(0, slash);
  }
  return ".";
}

// Async-signal-safe: write(2) only.
void say(const char* s) {
  for (size_t n = std::strlen(s); n > 0;) {
    const ssize_t w = ::write(2, s, n);
    if (w <= 0) return;
    s += w;
    n -= static_cast<size_t>(w);
  }
}

constexpr int kSignals[] = {SIGABRT, SIGSEGV, SIGBUS};
struct sigaction g_previous[3];  // what was there before ours, per kSignals entry

void onCrash(int sig) {
  if (g_depth.load() <= 0) {  // not the driver's: whatever handled it before (the default, LLVM's)
    for (int i = 0; i < 3; ++i)
      if (kSignals[i] == sig) ::sigaction(sig, &g_previous[i], nullptr);
    std::raise(sig);
    return;
  }
  say("brdfbake: the OpenCL driver crashed (");
  say(sig == SIGABRT ? "SIGABRT" : sig == SIGSEGV ? "SIGSEGV" : "SIGBUS");
  say(") while it built or ran kernels from its cache '");
  say(g_dir);
  say("'; PoCL does this when that directory is removed or changed while it links kernels. Run again (the "
      "cache is rebuilt), or give --cache-dir DIR on a directory nothing else changes.\n");
  ::_exit(kExitCantCreat);
}

void onExit() {
  if (g_depth.load() <= 0) return;
  say("brdfbake: the OpenCL driver ended the process while it built or ran kernels from its cache '");
  say(g_dir);
  say("' (its message is above): the directory's file system is full or cannot be written. Free space there "
      "or give --cache-dir DIR; the driver's temporaries (tempfile_*) may remain in that directory.\n");
  ::_exit(kExitIoErr);
}

// Puts onCrash in front, keeping what was there (the default, or the handlers LLVM installs when
// PoCL loads it) for signals that are not the driver's.
void putHandlersInFront() {
  struct sigaction sa {};
  sa.sa_handler = onCrash;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_NODEFER;
  for (int i = 0; i < 3; ++i) {
    struct sigaction old {};
    ::sigaction(kSignals[i], nullptr, &old);
    if (old.sa_handler == onCrash) continue;
    g_previous[i] = old;
    ::sigaction(kSignals[i], &sa, nullptr);
  }
}

// Whether a build log holds a compiler diagnostic (clang's "file:line:col: error: ...").
bool hasDiagnostic(const std::string& log) { return log.find("error:") != std::string::npos; }

}  // namespace

void checkDriverCacheSpace(const std::string& dir) {
  const std::string at = existingAncestor(dir);
  struct statvfs vfs {};
  if (::statvfs(at.c_str(), &vfs) != 0) return;  // cacheProblem() names an unusable directory
  const unsigned long long freeBytes = static_cast<unsigned long long>(vfs.f_bavail) * vfs.f_frsize;
  unsigned long long minFree = kDriverCacheMinFree;
  // For tests of the driver's own failure on a full file system: a lower limit.
  if (const char* test = std::getenv("BRDFBAKE_TEST_DRIVER_MIN_FREE")) minFree = std::strtoull(test, nullptr, 10);
  if (freeBytes >= minFree) return;
  throw Error(kExitIoErr, "the OpenCL driver's kernel cache '" + dir + "' has " + std::to_string(freeBytes >> 10) +
                              " KiB free; building the kernels needs up to " +
                              std::to_string(kDriverCacheMinFree >> 20) +
                              " MiB there: free space, or give --cache-dir DIR on another file system");
}

ExitCode driverFailureCode(const std::string& log, const std::string& dir) {
  if (hasDiagnostic(log)) return kExitSoftware;
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || ::access(dir.c_str(), W_OK | X_OK) != 0)
    return kExitCantCreat;
  return kExitSoftware;
}

std::string driverCacheHint(const std::string& log, const std::string& dir) {
  if (hasDiagnostic(log)) return "";
  return "\nThe driver gave no compiler diagnostic: on PoCL this is its kernel cache '" + dir +
         "' removed, full or unwritable during the build. Run again, or give --cache-dir DIR on a directory "
         "nothing else changes.";
}

DriverWork::DriverWork(const std::string& dir) {
  // Registered at the first scope, after the driver is loaded, so that it runs before the driver's
  // own exit handlers and static destructors.
  static std::once_flag registered;
  std::call_once(registered, [] {
    if (g_installed) std::atexit(onExit);
  });
  // LLVM puts its own crash handlers in front when PoCL loads it, after main installed ours.
  if (g_installed) putHandlersInFront();
  const size_t n = std::min(dir.size(), sizeof g_dir - 1);
  if (g_depth.fetch_add(1) == 0) {
    std::memcpy(g_dir, dir.data(), n);
    g_dir[n] = '\0';
  }
}

DriverWork::~DriverWork() { g_depth.fetch_sub(1); }

void installDriverGuards() {
  if (g_installed.exchange(true)) return;
  putHandlersInFront();
}

}  // namespace brdfbake
