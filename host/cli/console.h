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
  // timings: print the stages; progress: draw the progress line (callers pass isatty(2) && !--quiet).
  ConsoleObserver(bool timings, bool progress);
  ~ConsoleObserver() override;
  void stage(const std::string& kind, const std::string& what, double seconds) override;
  void progress(const std::string& what, const std::string& unit, double done, double total, double seconds) override;
  // --timings' last line: the whole command's wall time since this observer was made.
  void finish();

 private:
  void clearLine();
  bool timings_, progress_, lineShown_ = false;
  std::chrono::steady_clock::time_point start_;
};

// The observer a command's --timings and --quiet ask for (none when neither output is wanted).
std::shared_ptr<ConsoleObserver> consoleObserver(bool timings, bool quiet);

}  // namespace brdfbake
