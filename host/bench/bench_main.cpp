// brdfbake-bench: the default 128x128 GGX + smith-correlated split-sum table, baked by brdfbake's
// kernel at its default accuracy and by the common practice (Karis 2013: Hammersley importance
// sampling, 1024 samples per texel, plain C++ on 2 threads), timed in the same run and both
// measured against the host reference (adaptive Gauss-Kronrod in double).
//
// The usage below (kUsage) is what `brdfbake-bench --help` prints.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "brdfbake/table_kind.h"
#include "tables/error_model.h"
#include "bench/bench_util.h"
#include "bench/karis_mc.h"
#include "cl/device.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/models.h"
#include "reference/reference.h"

using namespace brdfbake;
using namespace brdfbake::bench;

namespace {
const char* const kUsage =
    R"(usage: brdfbake-bench [--size N] [--samples S] [--stride K] [--repeat R] [--device TEXT] [--times-only]
                      [--pair NDF+GAF]... [--all-pairs] [--albedo-avg] [--cold-start [--skip-all]] [--materials]
                      [--dielectric [--mc-log2 K]] [--dielectric-avg [--size N] [--pair NDF+GAF]]
                      [--merl FILE [--size N]] [--commit]
  --stride K: reference on every K-th texel per axis plus the first/last rows and columns
              (default 1: every texel; the reference takes a few seconds for all 16384).
  --times-only: skip the errors; times and ratio only.
  --pair NDF+GAF: time (and check) that pair's split sum instead of ggx + smith-correlated; the
              Karis MC baseline stays ggx + smith-correlated's (a time baseline, its errors
              are then not printed).
  --all-pairs [--pair NDF+GAF]...: no timing; every NDF/GAF pair's table (or the given ones;
              not charlie's, whose reference is tests/tables/microfacet/sheen_test.cpp's) against the reference
              (largest error, largest kernel bound, texels whose error exceeds their bound).
              ~11 minutes at --stride 8 on two cores, most of it the exact-Smith references.
  --albedo-avg: the albedo-avg table (size 32, texel centres) timed against the 32x32 albedo
              table it averages, then every pair's albedo-avg against the reference: the
              largest bound over all 32 entries, the error at every --stride-th r (default 8)
              plus r = 3/64, 5/64, 63/64 and the node-grid r = 0, 1/2, 1. ~10 minutes.
  --cold-start [--skip-all]: what a user waits for: `brdfbake bake` of the default set and of
              every pair (56 pairs, 173 tables), run as processes in --repeat rounds, each with
              HOME a fresh empty directory: its first run (empty PoCL and program caches; the
              programs the build prepared are found), then a warm run; the best and the slowest
              of each, and a first run with nothing prepared; as ratios against the Karis MC
              baseline timed in this run and against the best warm run. --skip-all: the default
              set only. ~2 minutes on 2 cores (host/bench/cold_start_bench.cpp).
  --materials: 32x32 dielectric albedo (ggx + smith-correlated, eta 1.5 and 1/1.5) and diffuse
              albedo (burley, oren-nayar) tables, kernel vs an S-sample Monte Carlo estimator of
              the same quantity: times, errors against the reference (dielectric on every
              --stride-th texel, default 4, plus edges; diffuse on all), kernel bounds.
              host/bench/materials_bench.cpp. ~2 minutes.
  --bounds [--pair NDF+GAF]... [--tables LIST] [--csv FILE]: how tight the claimed bounds are: every
              table of the default set (split-sum --size, albedo, albedo-avg, k_p) of each pair
              (default: ggx+smith-correlated, beckmann+smith, ggx+schlick-ggx, blinn-phong+implicit,
              gaussian+smith-correlated-exact) baked as brdfbake bakes it, brdf.error and each
              texel's claim against the true error; --tables splitsum,albedo measures only those
              (of splitsum, albedo, albedo-avg, kp). host/bench/bounds_bench.cpp.
  --probe-span [--pair NDF+GAF]... [--size N]: the interpolation probe with its quarter-texel
              steps over six texels of mu against kProbeMuTexels (tables/interp_probe.h), on
              every pair's split sum (both mu axes) and 32^2 albedo. host/bench/probe_bench.cpp.
              ~1 minute.
  --dielectric [--mc-log2 K]: the 32^3 rough-dielectric table (ggx + smith-correlated) timed
              against a 2^K-sample Monte Carlo per cell (default K = 23, Cycles' budget) on 27
              cells, scaled; both against the o-space reference. host/bench/dielectric_bench.cpp.
  --dielectric-avg [--size N] [--pair NDF+GAF]: the N x N dielectric-avg table (default 8, ggx +
              smith-correlated) baked as brdfbake bakes it, every stored value against the same
              rule run tight: the largest error against brdf.error. ~4 minutes at 8 (3 s an entry).
  --commit [--repeat R]: what the output directory's lock and the commit record cost: their
              steps timed against a warm default bake, both medians of R runs (at least 21), in
              the same run (host/bench/commit_bench.cpp). A few seconds.
  --ltc [--pair NDF+GAF] [--size N]: the pair's N x N LTC fit (default ggx + smith-correlated, 64)
              timed against the Karis MC baseline in the same run, best of --repeat; its mean and
              largest distance (host/bench/ltc_bench.cpp). ~1 minute at 64.
  --merl FILE [--size N]: a measured material's albedo (N texel centres, default 16) and
              albedo-avg tables baked as brdfbake bakes them, each claim against a rule above the
              ones it climbs (host/bench/merl_bench.cpp). ~2 minutes at 16.
)";
}  // namespace

namespace brdfbake {
int materialsBench(KernelRunner& runner, int samples, int repeat, int stride);  // materials_bench.cpp
int volumeBench(KernelRunner& runner, int repeat, int bigSize);                 // volume_bench.cpp
int dielectricBench(KernelRunner& runner, int samplesLog2);                     // dielectric_bench.cpp
int dielectricAvgBench(KernelRunner& runner, int n, int ndf, int gaf);          // dielectric_bench.cpp
int merlBench(const std::string& file, int size);                               // merl_bench.cpp
int ltcBench(KernelRunner& runner, int ndf, int gaf, int n, int samples, int repeat);  // ltc_bench.cpp
int commitBench(const std::string& device, int repeat);                         // commit_bench.cpp
int allPairs(const std::string& device, int n, int stride,
             const std::vector<std::pair<int, int>>& only);                                     // pairs_bench.cpp
int probeSpanBench(KernelRunner& runner, const std::vector<std::pair<int, int>>& only, int n);  // probe_bench.cpp
int coldStart(const std::string& device, int samples, int repeat, bool skipAll);                // cold_start_bench.cpp
int boundsBench(KernelRunner& runner, const std::vector<std::pair<int, int>>& pairs, int size, int stride,
                const std::string& csv, const std::vector<TableKind>& tables);  // bounds_bench.cpp
}  // namespace brdfbake

namespace {
// albedo-avg against albedo (ggx + smith-correlated, size 32), best of `repeat`, interleaved.
void avgVsAlbedo(KernelRunner& runner, int repeat, double* tAvg, double* tAlb) {
  runner.prepareAll(std::vector<KernelNeed>{{KernelNeed::Hemisphere, 0, 10}});
  *tAvg = *tAlb = 1e30;
  for (int r = 0; r < repeat; ++r) {
    *tAvg = std::min(*tAvg, best(1, [&] { runner.albedoAvg(0, 10, 32, false); }));
    *tAlb = std::min(*tAlb, best(1, [&] { runner.hemisphere(0, 10, 32, 32, false); }));
  }
}

// Every pair's albedo-avg (32 texel centres, and the node grid r = 0, 1/2, 1) against the reference.
int albedoAvgCheck(KernelRunner& runner, int stride, int repeat) {
  double tAvg, tAlb;
  avgVsAlbedo(runner, std::max(repeat, 5), &tAvg, &tAlb);
  std::printf("ggx + smith-correlated, size 32: albedo-avg %.4f s, albedo 32x32 %.4f s, ratio %.2f\n", tAvg, tAlb,
              tAvg / tAlb);
  const int n = 32;
  std::vector<int> rows;
  for (int j = 0; j < n; ++j)
    if (j % stride == 0 || j == 1 || j == 2 || j == n - 1) rows.push_back(j);
  std::printf("albedo-avg, every pair: bound over all %d texel centres; errors at r =", n);
  for (int j : rows) std::printf(" %d/64", 2 * j + 1);
  std::printf(" and the node grid r = 0, 1/2, 1\n");
  std::printf("%-12s %-20s %12s %12s %10s\n", "ndf", "gaf", "max error", "max claim", "over claim");
  double all = 0, allBound = 0;
  int over = 0;
  for (int ndf = 0; ndf < static_cast<int>(ndfNames().size()); ++ndf)
    for (int gaf = 0; gaf < static_cast<int>(gafNames().size()); ++gaf) {
      if (!pairSupported(ndf, gaf) || isSheenNdf(ndf)) continue;
      KernelTable t = runner.albedoAvg(ndf, gaf, n, false), tn = runner.albedoAvg(ndf, gaf, 3, true);
      struct Point {
        double r, value, bound;
      };
      std::vector<Point> pts;
      // each value's claim as the bake makes it (tables/error_model.h)
      auto claim = [&](const KernelTable& k, int j) {
        return k.err[j] + avgFloatArithmeticError(k.planes[0][j], ndf, gaf);
      };
      for (int j : rows) pts.push_back({(j + 0.5) / n, t.planes[0][j], claim(t, j)});
      for (int j = 0; j < 3; ++j) pts.push_back({j / 2.0, tn.planes[0][j], claim(tn, j)});
      std::vector<double> err(pts.size());
      onTwoThreads(pts.size(), [&](size_t k) { err[k] = rel(pts[k].value, reference::albedoAvg(ndf, gaf, pts[k].r)); });
      double worst = 0, bound = 0;
      int bad = 0;
      for (int j = 0; j < n; ++j) bound = std::max(bound, claim(t, j));
      for (size_t k = 0; k < pts.size(); ++k) {
        worst = std::max(worst, err[k]);
        bound = std::max(bound, pts[k].bound);
        if (err[k] > pts[k].bound) ++bad;
      }
      all = std::max(all, worst);
      allBound = std::max(allBound, bound);
      over += bad;
      std::printf("%-12s %-20s %12.2e %12.2e %10d\n", ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), worst, bound,
                  bad);
      std::fflush(stdout);
    }
  std::printf(
      "all pairs: largest error %.2e, largest claim %.2e (estimate + float model), %d values over their claim\n", all,
      allBound, over);
  return over == 0 && allBound <= 1e-5 ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv) {
  int n = 128, samples = 1024, stride = 1, repeat = 3;
  std::string device;
  bool timesOnly = false, everyPair = false, avgCheck = false, cold = false, skipAll = false, strideSet = false;
  bool materials = false, volume = false, dielectric = false, bounds = false, dielectricAvg = false, sizeSet = false;
  bool probeSpan = false, ltc = false;
  std::vector<std::pair<int, int>> pairs;
  std::string csv;
  std::vector<TableKind> boundsTables;  // --tables: the --bounds rows to measure
  int mcLog2 = 23;
  int volumeSize = 256;
  std::string merlFile;
  bool commit = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s: missing value\n", a.c_str());
        std::exit(64);
      }
      return argv[++i];
    };
    if (a == "--size") {
      n = std::atoi(next().c_str());
      sizeSet = true;
    } else if (a == "--samples")
      samples = std::atoi(next().c_str());
    else if (a == "--stride") {
      stride = std::atoi(next().c_str());
      strideSet = true;
    } else if (a == "--repeat")
      repeat = std::atoi(next().c_str());
    else if (a == "--device")
      device = next();
    else if (a == "--times-only")
      timesOnly = true;
    else if (a == "--all-pairs")
      everyPair = true;
    else if (a == "--albedo-avg")
      avgCheck = true;
    else if (a == "--cold-start")
      cold = true;
    else if (a == "--materials")
      materials = true;
    else if (a == "--volume")
      volume = true;
    else if (a == "--dielectric")
      dielectric = true;
    else if (a == "--dielectric-avg")
      dielectricAvg = true;
    else if (a == "--bounds")
      bounds = true;
    else if (a == "--probe-span")
      probeSpan = true;
    else if (a == "--merl")
      merlFile = next();
    else if (a == "--commit")
      commit = true;
    else if (a == "--ltc")
      ltc = true;
    else if (a == "--csv")
      csv = next();
    else if (a == "--tables") {
      const std::string v = next();
      std::istringstream in(v);
      for (std::string t; std::getline(in, t, ',');) {
        // the registry's names; --bounds measures the default set's four kinds
        TableKind kind = TableKind::SplitSum;
        bool known = true;
        try {
          kind = tableKind(t, "--tables");
        } catch (const Error&) {
          known = false;
        }
        if (!known || (kind != TableKind::SplitSum && kind != TableKind::Albedo && kind != TableKind::AlbedoAvg &&
                       kind != TableKind::Kp)) {
          std::fprintf(
              stderr,
              "brdfbake-bench: --tables: comma-separated, each of splitsum, albedo, albedo-avg, kp; got \"%s\"\n",
              v.c_str());
          return 64;
        }
        boundsTables.push_back(kind);
      }
    } else if (a == "--pair") {
      std::string v = next();
      size_t plus = v.find('+');
      try {
        if (plus == std::string::npos) throw Error(kExitUsage, "--pair: NDF+GAF, e.g. ggx+smith-correlated");
        int nd = ndfId(v.substr(0, plus), "--pair"), gf = gafId(v.substr(plus + 1), "--pair");
        checkPair(nd, gf, "--pair");
        pairs.push_back({nd, gf});
      } catch (const Error& e) {
        std::fprintf(stderr, "brdfbake-bench: %s\n", e.what());
        return 64;
      }
    } else if (a == "--mc-log2")
      mcLog2 = std::atoi(next().c_str());
    else if (a == "--volume-size")
      volumeSize = std::atoi(next().c_str());
    else if (a == "--skip-all")
      skipAll = true;
    else {
      std::fprintf(stderr, "brdfbake-bench: unknown option %s (brdfbake-bench --help lists them)\n", a.c_str());
      return 64;
    }
  }
  if (n < 1 || samples < 1 || stride < 1 || repeat < 1) {
    std::fprintf(stderr, "arguments must be >= 1\n");
    return 64;
  }
  try {
    if (cold) return coldStart(device, samples, repeat, skipAll);
    if (commit) return commitBench(device, std::max(repeat, 21));
    if (!merlFile.empty()) return merlBench(merlFile, sizeSet ? n : 16);  // on the host: no device
    if (everyPair) {
      for (const auto& pr : pairs)
        if (isSheenNdf(pr.first))
          throw Error(kExitUsage,
                      "--all-pairs --pair: charlie's pairs have their own reference (tests/tables/microfacet/sheen_test.cpp)");
      return allPairs(device, n, stride, pairs);
    }
    DeviceEntry dev = selectDevice(device);
    KernelRunner runner(dev.device);
    if (avgCheck) return albedoAvgCheck(runner, strideSet ? stride : 8, repeat);
    if (materials) return materialsBench(runner, samples, repeat, strideSet ? stride : 4);
    if (bounds) {
      if (pairs.empty())
        pairs = {{NDF_GGX, GAF_SMITH_CORRELATED},
                 {NDF_BECKMANN, GAF_SMITH},
                 {NDF_GGX, GAF_SCHLICK_GGX},
                 {NDF_BLINN_PHONG, GAF_IMPLICIT},
                 {NDF_GAUSSIAN, GAF_SMITH_CORRELATED_EXACT}};
      return boundsBench(runner, pairs, n, stride, csv, boundsTables);
    }
    if (probeSpan) return probeSpanBench(runner, pairs, n);
    if (dielectric) return dielectricBench(runner, std::max(1, std::min(mcLog2, 24)));
    if (dielectricAvg) {
      const int nd = pairs.empty() ? NDF_GGX : pairs[0].first,
                gf = pairs.empty() ? GAF_SMITH_CORRELATED : pairs[0].second;
      if ((nd != NDF_GGX && nd != NDF_BECKMANN) || (gf != GAF_SMITH && gf != GAF_SMITH_CORRELATED))
        throw Error(
            kExitUsage,
            "--dielectric-avg --pair: the rough dielectric takes ggx or beckmann with smith or smith-correlated");
      return dielectricAvgBench(runner, sizeSet ? n : 8, nd, gf);
    }
    if (volume) return volumeBench(runner, repeat, std::max(1, std::min(volumeSize, 1024)));
    if (ltc)
      return ltcBench(runner, pairs.empty() ? NDF_GGX : pairs[0].first,
                      pairs.empty() ? GAF_SMITH_CORRELATED : pairs[0].second, sizeSet ? std::min(n, 256) : 64,
                      samples, repeat);
    // the split sum of the first --pair (ggx + smith-correlated by default) against Karis's MC
    const int ndf = pairs.empty() ? NDF_GGX : pairs[0].first,
              gaf = pairs.empty() ? GAF_SMITH_CORRELATED : pairs[0].second;
    const std::string pairName = ndfNames()[ndf] + " + " + gafNames()[gaf];
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
        // as the bake refines (kernels/bake.cl BAKE_TARGET)
        if (brdf32::hemi_rel_error(h) > HEMI_BAKE_TARGET) {
          ++refined;
          h = brdf32::hemisphere_moments(ndf, gaf, p, mu, 1);
        }
      }
    double tn = seconds(t0);
    if (timesOnly) {
      std::printf("split-sum %dx%d, %s, device: %s (errors skipped)\n", n, n, pairName.c_str(), dev.name.c_str());
      std::printf(
          "brdfbake quadrature (OpenCL) %.4f s, Karis MC %d spp (C++, 2 threads) %.4f s, "
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

    std::printf("split-sum %dx%d, %s, device: %s\n", n, n, pairName.c_str(), dev.name.c_str());
    std::printf("errors measured on %zu texels (stride %d + edges) against adaptive GK in double\n", texels.size(),
                stride);
    std::printf("%-34s %10s %12s %12s\n", "method", "seconds", "max error", "kernel bound");
    std::printf("%-34s %10.4f %12.2e %12.2e\n", "brdfbake quadrature (OpenCL)", tq, maxQ, maxBound);
    char name[64];
    std::snprintf(name, sizeof name, "Karis MC %d spp (C++, 2 threads)", samples);
    // Karis's estimator is ggx + smith-correlated's: for another pair it is a time baseline only
    const bool mcSamePair = ndf == NDF_GGX && gaf == GAF_SMITH_CORRELATED;
    if (mcSamePair)
      std::printf("%-34s %10.4f %12.2e %12s   (rms %.2e)\n", name, tm, maxM, "-", rmsM);
    else
      std::printf("%-34s %10.4f %12s %12s   (ggx + smith-correlated: a time baseline here)\n", name, tm, "-", "-");
    std::printf("%-34s %10.4f   (same estimator, host C++, 1 thread; %d of %d texels refined)\n",
                "brdfbake quadrature (native)", tn, refined, n * n);
    std::printf("time ratio quadrature/MC: %.2f", tq / tm);
    if (mcSamePair) std::printf("   error ratio MC/quadrature: %.0f", maxM / std::max(maxQ, 1e-300));
    std::printf("\n");
  } catch (const Error& e) {
    std::fprintf(stderr, "brdfbake-bench: %s\n", e.what());
    return e.code();
  }
  return 0;
}
