// brdfbake-bench --commit: what one writer per directory and the commit record cost a warm bake.
// The default set is baked into a scratch directory R times (warm: the programs cached, the
// directory replaced each time), and in the same run the steps the lock and the record add are
// timed on that directory R times: lock, recover (nothing to finish: one directory read), write
// and sync the record, remove it and sync the directory, unlock. Printed: both medians and their
// ratio.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "brdfbake/brdfbake.h"
#include "formats/commit_record.h"

namespace brdfbake {

namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int commitBench(const std::string& device, int repeat) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("brdfbake_commit_bench_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  BakeRequest req = defaultRequest();  // ggx + smith-correlated, the four default tables
  req.outDir = dir.string();
  req.device = device;
  bakeToDirectory(req);  // warm up: programs built, directory created
  std::vector<double> bake, steps;
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const auto& e : fs::directory_iterator(dir))
    pairs.push_back({"." + e.path().filename().string() + ".brdfbake-tmp-bench", e.path().filename().string()});
  for (int r = 0; r < repeat; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    bakeToDirectory(req);
    bake.push_back(since(t0));
    t0 = std::chrono::steady_clock::now();
    {
      DirLock lock(dir.string(), true);
      recoverDirectory(dir.string());
      const std::string record = writeCommitRecord(dir.string(), pairs);
      removeCommitRecord(dir.string(), record);
    }
    steps.push_back(since(t0));
  }
  fs::remove_all(dir);
  const double b = median(bake), s = median(steps);
  std::printf("warm default bake (4 tables, median of %d): %.2f ms\n", repeat, 1e3 * b);
  std::printf("lock + recover + commit record (median of %d): %.3f ms = %.2f%% of the bake\n", repeat, 1e3 * s,
              100 * s / b);
  return 0;
}

}  // namespace brdfbake
