// brdfbake-bench: the default 128x128 GGX + smith-correlated split-sum table, baked by brdfbake's
// kernel at its default accuracy and by the common practice (Karis 2013: Hammersley importance
// sampling, 1024 samples per texel, plain C++ on 2 threads), timed in the same run and both
// measured against the host reference (adaptive Gauss-Kronrod in double).
//
// usage: brdfbake-bench [--size N] [--samples S] [--stride K] [--repeat R] [--device TEXT] [--times-only]
//   --stride K: reference on every K-th texel per axis plus the first/last rows and columns
//               (default 1: every texel; the reference takes a few seconds for all 16384).
//   --times-only: skip the errors; times and ratio only.
//   --all-pairs: no timing; every NDF/GAF pair's table against the reference (largest error,
//               largest kernel bound, texels whose error exceeds their bound). ~5 minutes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "bench/karis_mc.h"
#include "cl/device.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/models.h"
#include "reference/reference.h"

using namespace brdfbake;

namespace {
double rel(double got, double want) { return std::fabs(got - want) / std::max(1.0, std::fabs(want)); }

// The texels whose errors are measured: every stride-th per axis, plus the table's edges.
std::vector<std::pair<int, int>> sampledTexels(int n, int stride) {
  std::vector<std::pair<int, int>> texels;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if ((i % stride == 0 && j % stride == 0) || i == 0 || j == 0 || i == n - 1 || j == n - 1) texels.push_back({i, j});
  return texels;
}

// f(k) for every k in [0, count), on 2 threads (the reference is the slow part).
template <class F>
void onTwoThreads(size_t count, F f) {
  std::thread th([&] {
    for (size_t k = 1; k < count; k += 2) f(k);
  });
  for (size_t k = 0; k < count; k += 2) f(k);
  th.join();
}

// Every pair's n x n texel-centre split-sum table against the reference on the sampled texels.
// Returns 0 if every error is within its bound.
int allPairs(KernelRunner& runner, int n, int stride) {
  const double allowance = 1e-6;  // host/bake: float arithmetic on the device
  std::vector<std::pair<int, int>> texels = sampledTexels(n, stride);
  std::printf("split-sum %dx%d, every NDF/GAF pair, errors on %zu texels (stride %d + edges)\n", n, n,
              texels.size(), stride);
  std::printf("%-12s %-20s %12s %12s %10s\n", "ndf", "gaf", "max error", "max bound", "over bound");
  double all = 0;
  int over = 0;
  for (int ndf = 0; ndf < static_cast<int>(ndfNames().size()); ++ndf)
    for (int gaf = 0; gaf < static_cast<int>(gafNames().size()); ++gaf) {
      KernelTable t = runner.hemisphere(ndf, gaf, n, n, false);
      std::vector<double> err(texels.size());
      onTwoThreads(texels.size(), [&](size_t k) {
        auto [i, j] = texels[k];
        size_t x = static_cast<size_t>(j) * n + i;
        reference::Moments ref = reference::albedo(ndf, gaf, (j + 0.5) / n, (i + 0.5) / n);
        err[k] = std::max({rel(t.planes[0][x], ref.a), rel(t.planes[1][x], ref.b), rel(t.planes[2][x], ref.e())});
      });
      double worst = 0, bound = 0;
      int bad = 0;
      for (size_t k = 0; k < texels.size(); ++k) {
        double b = t.err[static_cast<size_t>(texels[k].second) * n + texels[k].first];
        worst = std::max(worst, err[k]);
        bound = std::max(bound, b);
        if (err[k] > b + allowance) ++bad;
      }
      all = std::max(all, worst);
      over += bad;
      std::printf("%-12s %-20s %12.2e %12.2e %10d\n", ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), worst, bound, bad);
    }
  std::printf("all pairs: largest error %.2e, %d texels over their bound\n", all, over);
  return over == 0 ? 0 : 1;
}

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv) {
  int n = 128, samples = 1024, stride = 1, repeat = 3;
  std::string device;
  bool timesOnly = false, everyPair = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) { std::fprintf(stderr, "%s: missing value\n", a.c_str()); std::exit(64); }
      return argv[++i];
    };
    if (a == "--size") n = std::atoi(next().c_str());
    else if (a == "--samples") samples = std::atoi(next().c_str());
    else if (a == "--stride") stride = std::atoi(next().c_str());
    else if (a == "--repeat") repeat = std::atoi(next().c_str());
    else if (a == "--device") device = next();
    else if (a == "--times-only") timesOnly = true;
    else if (a == "--all-pairs") everyPair = true;
    else { std::fprintf(stderr, "unknown option %s\n", a.c_str()); return 64; }
  }
  if (n < 1 || samples < 1 || stride < 1 || repeat < 1) { std::fprintf(stderr, "arguments must be >= 1\n"); return 64; }
  const int ndf = 0, gaf = 10;  // ggx + smith-correlated
  try {
    DeviceEntry dev = selectDevice(device);
    KernelRunner runner(dev.device);
    if (everyPair) return allPairs(runner, n, stride);
    runner.hemisphere(ndf, gaf, 1, 1, false);  // builds the program: not part of the timing

    double tq = 1e30, tm = 1e30;
    KernelTable q;
    std::vector<std::vector<float>> mc;
    for (int r = 0; r < repeat; ++r) {  // interleaved, best of `repeat` for each
      auto t0 = std::chrono::steady_clock::now();
      q = runner.hemisphere(ndf, gaf, n, n, false);
      tq = std::min(tq, seconds(t0));
      t0 = std::chrono::steady_clock::now();
      mc = karisSplitSumMC(n, samples, 2);
      tm = std::min(tm, seconds(t0));
    }

    // The same estimator compiled natively for the host (brdf32, float), one thread: shows how
    // fast the OpenCL device runs this code per core, and how many texels needed the refinement.
    auto t0 = std::chrono::steady_clock::now();
    int refined = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        float mu = (i + 0.5f) / n, r = (j + 0.5f) / n;
        brdf32::BrdfParams p = brdf32::brdf_params(ndf, gaf, r);
        brdf32::HemiResult h = brdf32::hemisphere_moments(ndf, gaf, p, mu, 0);
        if (brdf32::hemi_rel_error(h) > 8e-6f) {  // BAKE_TARGET in kernels/bake.cl
          ++refined;
          h = brdf32::hemisphere_moments(ndf, gaf, p, mu, 1);
        }
      }
    double tn = seconds(t0);
    if (timesOnly) {
      std::printf("split-sum %dx%d, ggx + smith-correlated, device: %s (errors skipped)\n", n, n, dev.name.c_str());
      std::printf("brdfbake quadrature (OpenCL) %.4f s, Karis MC %d spp (C++, 2 threads) %.4f s, "
                  "native 1 thread %.4f s (%d texels refined); time ratio quadrature/MC: %.2f\n",
                  tq, samples, tm, tn, refined, tq / tm);
      return 0;
    }

    // errors against the reference on the sampled texels (2 threads)
    std::vector<std::pair<int, int>> texels = sampledTexels(n, stride);
    std::vector<double> errQ(texels.size()), errM(texels.size()), sq(texels.size()), bound(texels.size());
    onTwoThreads(texels.size(), [&](size_t k) {
      auto [i, j] = texels[k];
      double mu = (i + 0.5) / n, r = (j + 0.5) / n;
      reference::Moments ref = reference::albedo(ndf, gaf, r, mu);
      size_t t = static_cast<size_t>(j) * n + i;
      errQ[k] = std::max(rel(q.planes[0][t], ref.a), rel(q.planes[1][t], ref.b));
      errM[k] = std::max(rel(mc[0][t], ref.a), rel(mc[1][t], ref.b));
      sq[k] = std::pow(mc[0][t] - ref.a, 2) + std::pow(mc[1][t] - ref.b, 2);
      bound[k] = q.err[t];
    });
    double maxQ = *std::max_element(errQ.begin(), errQ.end());
    double maxM = *std::max_element(errM.begin(), errM.end());
    double rmsM = 0;
    for (double s : sq) rmsM += s;
    rmsM = std::sqrt(rmsM / (2.0 * sq.size()));
    double maxBound = *std::max_element(bound.begin(), bound.end());

    std::printf("split-sum %dx%d, ggx + smith-correlated, device: %s\n", n, n, dev.name.c_str());
    std::printf("errors measured on %zu texels (stride %d + edges) against adaptive GK in double\n", texels.size(), stride);
    std::printf("%-34s %10s %12s %12s\n", "method", "seconds", "max error", "kernel bound");
    std::printf("%-34s %10.4f %12.2e %12.2e\n", "brdfbake quadrature (OpenCL)", tq, maxQ, maxBound);
    char name[64];
    std::snprintf(name, sizeof name, "Karis MC %d spp (C++, 2 threads)", samples);
    std::printf("%-34s %10.4f %12.2e %12s   (rms %.2e)\n", name, tm, maxM, "-", rmsM);
    std::printf("%-34s %10.4f   (same estimator, host C++, 1 thread; %d of %d texels refined)\n",
                "brdfbake quadrature (native)", tn, refined, n * n);
    std::printf("time ratio quadrature/MC: %.2f   error ratio MC/quadrature: %.0f\n", tq / tm, maxM / std::max(maxQ, 1e-300));
  } catch (const Error& e) {
    std::fprintf(stderr, "brdfbake-bench: %s\n", e.what());
    return e.code();
  }
  return 0;
}
