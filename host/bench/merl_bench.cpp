// brdfbake-bench --merl FILE [--size N]: how tight a measured material's claims are. The albedo
// table (N texel centres, default 16) and the albedo-avg table are baked as brdfbake bakes them
// (merlTable), timed, and every stored value is compared with a rule above the ones they climb:
// the texels with the h-space rule (30,29) (their ladder stops at (25,24)), E_avg with the
// direct rule n = 10 (its ladder stops at 8). Prints each table's brdf.error, the largest error
// of a stored value, and their ratio (docs/merl.md, "Tight claims"). About 2 minutes at 16.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "formats/merl.h"
#include "materials/merl_albedo.h"

namespace brdfbake {

int merlBench(const std::string& file, int size) {
  using bench::onTwoThreads;
  using bench::seconds;
  MerlData d = readMerl(file);
  RusinkiewiczFn f = merlFunction(d);
  const std::string name = std::filesystem::path(file).stem().string();
  std::printf("MERL file %s: the albedo table (%d texel centres) and E_avg, claims against rules above the ladders\n",
              file.c_str(), size);
  std::printf("%-10s %8s %12s %14s %8s %s\n", "table", "seconds", "brdf.error", "largest error", "ratio", "reference");

  auto t0 = std::chrono::steady_clock::now();
  TableImage albedo = merlTable(d, name, MerlTableSpec{"albedo", false, ""}, size, false, false);
  const double ta = seconds(t0);
  std::vector<std::array<double, 3>> ref(size);
  onTwoThreads(size, [&](size_t i) { ref[i] = hSpaceIntegral(f, (i + 0.5) / size, HSpaceRule{30, 29}); });
  double worst = 0;
  for (int i = 0; i < size; ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::fabs(double(albedo.planes[c][i]) - ref[i][c]) / std::max(1.0, std::fabs(ref[i][c])));
  const double ca = albedo.floats["brdf.error"];
  std::printf("%-10s %8.1f %12.3e %14.3e %8.2f %s\n", "albedo", ta, ca, worst, ca / worst, "h-space rule (30,29)");

  t0 = std::chrono::steady_clock::now();
  TableImage avg = merlTable(d, name, MerlTableSpec{"albedo-avg", true, ""}, 1, false, false);
  const double tv = seconds(t0);
  std::array<double, 3> q = directAlbedoAvgRule(f, 10);
  double worstAvg = 0;
  for (int c = 0; c < 3; ++c)
    worstAvg = std::max(worstAvg, std::fabs(double(avg.planes[c][0]) - q[c]) / std::max(1.0, std::fabs(q[c])));
  const double cv = avg.floats["brdf.error"];
  std::printf("%-10s %8.1f %12.3e %14.3e %8.2f %s\n", "albedo-avg", tv, cv, worstAvg, cv / worstAvg,
              "direct rule n = 10");
  const bool honest = ca >= worst && cv >= worstAvg;
  std::printf("%s\n", honest ? "every claim holds" : "A CLAIM IS BELOW ITS ERROR");
  return honest ? 0 : 1;
}

}  // namespace brdfbake
