// The terminal's view of a running bake (cli/console.h).
#include "cli/console.h"

#include <unistd.h>

#include <cstdio>

namespace brdfbake {

ConsoleObserver::ConsoleObserver(bool timings, bool progress, bool lines)
    : timings_(timings), progress_(progress), lines_(lines), start_(std::chrono::steady_clock::now()) {
  if (timings_) std::fprintf(stderr, "timings (wall seconds):\n");
}

ConsoleObserver::~ConsoleObserver() { clearLine(); }

void ConsoleObserver::clearLine() {
  if (!lineShown_) return;
  std::fputs("\r\033[K", stderr);  // carriage return, erase to the end of the line
  std::fflush(stderr);
  lineShown_ = false;
}

void ConsoleObserver::stage(const std::string& kind, const std::string& what, double seconds) {
  clearLine();
  if (!timings_) return;
  std::fprintf(stderr, "  %8.3f  %-7s  %s\n", seconds, kind.c_str(), what.c_str());
}

void ConsoleObserver::progress(const std::string& what, const std::string& unit, double done, double total,
                               double seconds) {
  // only for a table that has run for a second: short ones would flicker
  if (!progress_ || seconds < 1.0 || total <= 0) return;
  if (done >= total) {
    clearLine();
    return;
  }
  const double left = done > 0 ? seconds * (total - done) / done : 0;
  char line[512];
  std::snprintf(line, sizeof line, "%s: %3.0f%% (%.0f of %.0f %s), %.1f s, about %.0f s left", what.c_str(),
                100 * done / total, done, total, unit.c_str(), seconds, left + 0.5);
  if (lines_) {
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (now - lastLine_ < 2) return;
    lastLine_ = now;
    std::fprintf(stderr, "brdfbake: %s\n", line);
    return;
  }
  std::fprintf(stderr, "\r\033[K%s", line);
  std::fflush(stderr);
  lineShown_ = true;
}

void ConsoleObserver::finish() {
  clearLine();
  if (timings_)
    std::fprintf(stderr, "  %8.3f  total    since the command started\n",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
}

std::shared_ptr<ConsoleObserver> consoleObserver(bool timings, bool quiet, bool forceProgress) {
  const bool terminal = ::isatty(STDERR_FILENO);
  const bool progress = (!quiet && terminal) || forceProgress;
  if (!timings && !progress) return nullptr;
  return std::make_shared<ConsoleObserver>(timings, progress, progress && !terminal);
}

}  // namespace brdfbake
