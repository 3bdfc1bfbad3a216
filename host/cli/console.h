// What a bake shows on the terminal while it runs (brdfbake/observer.h): with --timings, each stage
// and its seconds; on a terminal, a progress line for a table that takes longer than a second.
// Both go to stderr, never into the report on stdout or the files.
#pragma once
#include <chrono>
#include <memory>
#include <string>

#include "brdfbake/observer.h"

namespace brdfbake {

class ConsoleObserver : public BakeObserver {
 public:
  // timings: print the stages; progress: draw the progress line (callers pass isatty(2) && !--quiet);
  // lines: progress as whole lines, one every 2 s at most (--progress into a log: no escapes)
  ConsoleObserver(bool timings, bool progress, bool lines = false);
  ~ConsoleObserver() override;
  void stage(const std::string& kind, const std::string& what, double seconds) override;
  void progress(const std::string& what, const std::string& unit, double done, double total, double seconds) override;
  // --timings' last line: the whole command's wall time since this observer was made.
  void finish();

 private:
  void clearLine();
  bool timings_, progress_, lines_, lineShown_ = false;
  double lastLine_ = -10;
  std::chrono::steady_clock::time_point start_;
};

// The observer a command's --timings, --quiet and --progress ask for (none when no output is
// wanted): the progress line on a terminal unless --quiet; with --progress also into a file or a
// pipe, as whole lines.
std::shared_ptr<ConsoleObserver> consoleObserver(bool timings, bool quiet, bool forceProgress = false);

}  // namespace brdfbake
