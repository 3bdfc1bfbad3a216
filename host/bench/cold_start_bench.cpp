// brdfbake-bench --cold-start: what a user waits for, `brdfbake bake` of the default set and of
// every pair run as processes, first runs against warm ones and both against the Karis Monte Carlo
// split sum timed in this process (usage: bench_main.cpp; figures: docs/performance.md).
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/karis_mc.h"
#include "common/errors.h"
#include "common/models.h"

namespace brdfbake {

using namespace bench;

namespace {
// --cold-start runs the brdfbake next to this program, as a user does: `brdfbake bake` with HOME a
// fresh empty directory and no cache variables set (PoCL's cache and the program cache both start
// empty; the programs the build prepared, build/programs, are found as a fresh checkout finds
// them), then again in the same HOME (warm). Returns the process's wall seconds.
double timeBake(const std::string& exe, const std::string& home, const std::vector<std::string>& args,
                const std::string& device, bool prepared) {
  auto t0 = std::chrono::steady_clock::now();
  pid_t pid = fork();
  if (pid == 0) {
    int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
      dup2(null, 1);
      dup2(null, 2);
    }
    setenv("HOME", home.c_str(), 1);
    for (const char* v : {"POCL_CACHE_DIR", "XDG_CACHE_HOME", "BRDFBAKE_PROGRAM_CACHE", "BRDFBAKE_PREPARED_PROGRAMS"})
      unsetenv(v);
    if (!prepared) setenv("BRDFBAKE_PREPARED_PROGRAMS", "off", 1);
    if (chdir(home.c_str()) != 0) _exit(127);
    std::vector<const char*> argv = {exe.c_str(), "bake"};
    for (const auto& a : args) argv.push_back(a.c_str());
    if (!device.empty()) {
      argv.push_back("--device");
      argv.push_back(device.c_str());
    }
    argv.push_back(nullptr);
    execv(exe.c_str(), const_cast<char* const*>(argv.data()));
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  double t = seconds(t0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error(kExitSoftware, exe + " bake failed (status " + std::to_string(status) + ")");
  return t;
}

std::string freshHome() {
  char tmpl[] = "/tmp/brdfbake-bench-homeXXXXXX";
  if (!mkdtemp(tmpl)) throw Error(kExitCantCreat, "cannot create a temporary HOME");
  return tmpl;
}

void removeTree(const std::string& dir) {
  std::string rm = "rm -rf '" + dir + "'";
  if (std::system(rm.c_str()) != 0) std::fprintf(stderr, "could not remove %s\n", dir.c_str());
}
}  // namespace

int coldStart(const std::string& device, int samples, int repeat, bool skipAll) {
  char self[4096];
  ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
  if (len <= 0) throw Error(kExitSoftware, "cannot find this program's path");
  const std::string here(self, static_cast<size_t>(len));
  const std::string exe = here.substr(0, here.find_last_of('/')) + "/brdfbake";
  if (access(exe.c_str(), X_OK) != 0) throw Error(kExitUnavailable, exe + ": not found (build the brdfbake target)");
  // the baseline, in this process
  double tm = best(repeat, [&] { karisSplitSumMC(128, samples, 2); });
  std::printf(
      "%s bake, %d rounds, each with HOME a fresh empty directory: its first run (cold: empty PoCL and "
      "program caches), then a warm run; the best of each\n",
      exe.c_str(), repeat);
  std::printf("baseline: Karis MC %d spp split-sum 128x128 (C++, 2 threads) %.4f s\n", samples, tm);
  std::printf("%-46s %9s %8s %8s\n", "what", "seconds", "/ MC", "/ warm");
  // every pair: the four microfacet NDFs with every GAF but the sheen ones, and charlie with its four
  std::string gafs;
  for (int g = 0; g < static_cast<int>(gafNames().size()); ++g)
    if (!isSheenGaf(g)) gafs += (gafs.empty() ? "" : ",") + gafNames()[g];
  struct Set {
    std::string name;
    std::vector<std::vector<std::string>> bakes;  // one process each
  };
  std::vector<Set> sets = {{"default set (4 tables)", {{"-o", "out"}}},
                           {"every pair (56 pairs: 173 tables)",
                            {{"--ndf", "ggx,beckmann,blinn-phong,gaussian", "--gaf", gafs, "-o", "all"},
                             {"--ndf", "charlie", "--gaf", "none,implicit,charlie-smith,neubelt", "-o", "sheen"}}}};
  for (const Set& set : sets) {
    if (skipAll && set.bakes.size() > 1) break;
    auto timeSet = [&](const std::string& home, bool prepared) {
      double t = 0;
      for (const auto& args : set.bakes) t += timeBake(exe, home, args, device, prepared);
      return t;
    };
    // `repeat` rounds, each in a fresh HOME: its first run, then a warm one. The best of each, so
    // that both sides of the first-run ratio are minima over as many samples (one first run
    // against the best of three warm ones read this machine's noise as a first-run cost), and the
    // slowest first and warm runs too (the spread of the machine's noise).
    double cold = 1e30, coldWorst = 0, warm = 1e30, warmWorst = 0;
    for (int r = 0; r < repeat; ++r) {
      const std::string home = freshHome();
      const double c = timeSet(home, true);
      cold = std::min(cold, c);
      coldWorst = std::max(coldWorst, c);
      const double w = timeSet(home, true);
      warm = std::min(warm, w);
      warmWorst = std::max(warmWorst, w);
      removeTree(home);
    }
    const std::string bare = freshHome();
    const double source = timeSet(bare, false);
    removeTree(bare);
    auto row = [&](const std::string& what, double t) {
      std::printf("%-46s %9.3f %8.2f %8.2f\n", what.c_str(), t, t / tm, t / warm);
    };
    row(set.name + ", warm", warm);
    row(set.name + ", warm, slowest", warmWorst);
    row(set.name + ", first run", cold);
    row(set.name + ", first run, slowest", coldWorst);
    row(set.name + ", first run, nothing prepared", source);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace brdfbake
