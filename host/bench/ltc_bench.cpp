// brdfbake-bench --ltc: the LTC fit of one pair (default ggx + smith-correlated, 64^2) timed against
// the Karis Monte Carlo split sum (128^2, --samples spp, C++ on 2 threads) in the same run, with the
// fit's distances and its budget's cost per texel.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "bench/karis_mc.h"
#include "common/models.h"
#include "tables/ltc/ltc_fit.h"

namespace brdfbake {

int ltcBench(KernelRunner& runner, int ndf, int gaf, int n, int samples, int repeat) {
  auto secs = [](auto&& f) {
    auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  const LtcLobeSpec lobe{ndf, gaf};
  fitLtc(runner, lobe, 2);  // builds the programs: not part of the timing
  double tm = 1e30, tf = 1e30;
  LtcFit f;
  for (int k = 0; k < repeat; ++k) {
    tm = std::min(tm, secs([&] { karisSplitSumMC(128, samples, 2); }));
    tf = std::min(tf, secs([&] { f = fitLtc(runner, lobe, n); }));
  }
  double sum = 0, worst = 0, evals = 0;
  for (size_t t = 0; t < f.tv.size(); ++t) {
    sum += f.tv[t];
    worst = std::max<double>(worst, f.tv[t]);
    evals += f.evals[t];
  }
  const double texels = static_cast<double>(n) * n;
  std::printf("baseline: Karis MC %d spp split-sum 128x128 (C++, 2 threads) %.4f s\n", samples, tm);
  std::printf("ltc %s + %s %dx%d: %.2f s (%.1f x the baseline; magnitudes %.3f s, fits %.2f s), %.1f ms a texel,\n"
              "  %.0f objective evaluations a texel on average; distance mean %.4f, largest %.4f (best of %d)\n",
              ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), n, n, tf, tf / tm, f.magnitudeSeconds, f.seconds,
              1e3 * tf / texels, evals / texels, sum / texels, worst, repeat);
  return 0;
}

}  // namespace brdfbake
