// brdfbake-bench --probe-span [--pair NDF+GAF]... [--size N]: whether the interpolation probe's
// quarter-texel steps may stop at kProbeMuTexels texels of mu (tables/interp_probe.h). For each
// pair (default: every pair, charlie's included) it bakes the split sum at --size (default 128)
// on both mu axes and the 32^2 albedo, as brdfbake bakes them, and probes each table twice: with
// the steps over six texels of mu and over kProbeMuTexels. Prints both maxima, the
// brdf.interp-error each gives (the larger of the texels' estimate and kProbeMargin times the
// maximum), the probes' seconds and the estimate from the texels alone; exits 1 where the shorter
// span gives a smaller brdf.interp-error.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "cl/runner.h"
#include "brdfbake/table_kind.h"
#include "common/models.h"
#include "tables/interp_estimate.h"
#include "tables/interp_probe.h"
#include "tables/microfacet/microfacet.h"

namespace brdfbake {
using namespace bench;

int probeSpanBench(KernelRunner& runner, const std::vector<std::pair<int, int>>& only, int n) {
  const int wide = 6;
  std::printf("interpolation probe: quarter steps over %d texels of mu against %d (tables/interp_probe.h)\n", wide,
              kProbeMuTexels);
  std::printf("%-12s %-20s %-9s %5s %5s %11s %11s %11s %11s %7s %7s %11s\n", "ndf", "gaf", "table", "size", "axis",
              "max (6)", "max (2)", "interp (6)", "interp (2)", "s (6)", "s (2)", "estimate");
  int worse = 0, lower = 0, tables = 0;
  double t6 = 0, t2 = 0;
  for (int ndf = 0; ndf < static_cast<int>(ndfNames().size()); ++ndf)
    for (int gaf = 0; gaf < static_cast<int>(gafNames().size()); ++gaf) {
      if (!pairSupported(ndf, gaf)) continue;
      if (!only.empty() && std::find(only.begin(), only.end(), std::pair{ndf, gaf}) == only.end()) continue;
      struct Shape {
        TableKind kind;
        int size;
        bool sqrtAxis;
      };
      for (const Shape& sh : {Shape{TableKind::SplitSum, n, false}, Shape{TableKind::SplitSum, n, true},
                              Shape{TableKind::Albedo, 32, false}}) {
        TableJob job = TableJob();
        job.kind = sh.kind;
        job.ndf = ndf;
        job.gaf = gaf;
        job.width = job.height = sh.size;
        job.muSqrt = sh.sqrtAxis;
        job.path = "probe.exr";
        double secs = 0;
        const TableImage img = computeTable(runner, job, &secs);
        const std::vector<ProbePlane> planes = probePlanes(job);
        double a = 0, b = 0;
        const double sa = best(1, [&] { a = probeInterpolation(runner, job, img, planes, wide); });
        const double sb = best(1, [&] { b = probeInterpolation(runner, job, img, planes, kProbeMuTexels); });
        t6 += sa;
        t2 += sb;
        ++tables;
        const double est = estimateInterpolation(img, job.nodeGrid).total();
        const double ia = std::max(est, kProbeMargin * a), ib = std::max(est, kProbeMargin * b);
        if (b < a) ++lower;
        if (ib < ia) ++worse;
        std::printf("%-12s %-20s %-9s %5d %5s %11.5g %11.5g %11.5g %11.5g %7.4f %7.4f %11.5g%s\n",
                    ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), tableName(sh.kind).c_str(), sh.size,
                    sh.sqrtAxis ? "sqrt" : "mu", a, b, ia, ib, sa, sb, est, ib < ia ? "  SMALLER" : "");
        std::fflush(stdout);
      }
    }
  std::printf(
      "%d tables: %d where %d texels of steps give a smaller brdf.interp-error than %d (%d a smaller "
      "maximum); probes %.2f s against %.2f s (%.2f)\n",
      tables, worse, kProbeMuTexels, wide, lower, t2, t6, t2 / t6);
  return worse == 0 ? 0 : 1;
}

}  // namespace brdfbake
