#include "tables/ltc/ltc_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/errors.h"
#include "common/format.h"
#include "common/models.h"
#include "tables/ladder.h"
#include "tables/ltc/ltc_fit.h"
#include "tables/ltc/ltc_reference.h"

namespace brdfbake {

namespace {

// The reference distance at every texel of a fit (1 where the lobe carries no light, as the fit
// states), on two threads; err receives each one's own error estimate.
std::vector<double> referenceDistances(const LtcLobeSpec& lobe, const LtcFit& f, std::vector<double>* err) {
  const int n = f.n;
  const size_t texels = static_cast<size_t>(n) * n;
  std::vector<double> tv(texels, 1.0);
  if (err) err->assign(texels, 0.0);
  ladder::onTwoThreads(texels, [&](size_t t) {
    if (f.e[t] < kLtcNegligibleE) return;
    const LtcDistance d = ltcDistanceReference(lobe, n, f.store, f.e, t);
    tv[t] = d.tv;
    if (err) (*err)[t] = d.err;
  });
  return tv;
}

// The lobe a one-lobe request names: --diffuse MODEL, or one --ndf and one --gaf.
LtcLobeSpec requestedLobe(const BakeRequest& req) {
  if (req.diffuse >= 0) {
    if (req.diffuse == DIFFUSE_LAMBERT)
      throw Error(kExitUsage, "--diffuse lambert: its LTC is the clamped cosine itself; give another --diffuse");
    return LtcLobeSpec{-1, -1, req.diffuse};
  }
  if (req.ndfs.size() != 1 || req.gafs.size() != 1)
    throw Error(kExitUsage, "convergence measures one lobe: give one --ndf and one --gaf, or one --diffuse");
  if (!pairSupported(req.ndfs[0], req.gafs[0]))
    throw Error(kExitUsage, "--ndf " + ndfNames()[req.ndfs[0]] + " --gaf " + gafNames()[req.gafs[0]] +
                                ": --table ltc fits the pairs --table albedo takes");
  return LtcLobeSpec{req.ndfs[0], req.gafs[0]};
}

}  // namespace

// Rungs: the bake's distance estimate (multiple importance sampling over 16 shifted lattices, in
// double on the host where float cannot resolve the lobe) at rising points per strategy, on the
// LTCs of one fit at the default budget, each texel against the reference quadrature. A rung's
// estimate is the bake's claim for the distance (4 standard errors and E's claim); the bake uses
// 256 points.
Ladder ltcLadder(BakeContext& ctx, const BakeRequest& req) {
  const LtcLobeSpec lobe = requestedLobe(req);
  const int n = ladder::pointsPerAxis(req, 8, 2, 32, "ltc");
  KernelRunner& kr = ctx.runner();
  fitLtc(kr, lobe, 2);  // builds the program: not part of a rung's time
  std::fprintf(stderr, "convergence: fitting %d x %d texels\n", n, n);
  const LtcFit f = fitLtc(kr, lobe, n);
  const size_t texels = static_cast<size_t>(n) * n;
  std::fprintf(stderr, "convergence: reference at %zu texels\n", texels);
  double t0 = ladder::now();
  std::vector<double> refErr;
  const std::vector<double> ref = referenceDistances(lobe, f, &refErr);
  const double refSeconds = ladder::now() - t0;
  Ladder L;
  L.table = "ltc of " + lobe.name() + ", the distance of a " + std::to_string(n) + " x " + std::to_string(n) +
            " fit (r and sqrt(1 - mu) on nodes)";
  double refErrMax = 0;
  for (double e : refErr) refErrMax = std::max(refErrMax, e);
  for (int pts : {64, 128, 256, 512, 1024}) {
    LtcBudget b;
    b.finalPoints = pts;
    std::vector<std::vector<float>> m;
    const double secs = ladder::best3([&] { m = measureLtc(kr, lobe, n, f.store, f.e, b); });
    std::vector<double> v(texels), e(texels);
    for (size_t t = 0; t < texels; ++t) {
      v[t] = m[0][t];
      e[t] = m[1][t] + ltcMagnitudeShare(f.e[t], f.eBound[t]);  // as fitLtc adds it
    }
    L.rungs.push_back(
        ladder::rung("distance estimate (MIS, 16 shifts)", std::to_string(pts) + " points", secs, v, e, ref));
  }
  L.note =
      "The reference (1 - int min(p, D) in the LTC's cosine coordinates by nested adaptive Gauss-Kronrod in "
      "double, tables/ltc/ltc_reference.h) took " +
      fmt3(refSeconds) + " s for " + std::to_string(texels) + " texels; its own largest error estimate " +
      fmtG(refErrMax) + ". The fit itself (" + fmt3(f.seconds) +
      " s at the default budget) is measured by brdfbake-bench --ltc\n";
  return L;
}

// The fits' corners against the reference: r = 0 (alpha = 1e-5) and r = 1 at mu = 1 and at the
// grazing cap, for a specular pair, a sheen pair and a diffuse model.
void ltcStress(BakeContext& ctx, std::vector<StressPoint>& out) {
  const int n = 8;
  const LtcLobeSpec lobes[] = {
      {NDF_GGX, GAF_SMITH_CORRELATED}, {NDF_CHARLIE, GAF_CHARLIE_SMITH}, {-1, -1, DIFFUSE_OREN_NAYAR}};
  for (const LtcLobeSpec& lobe : lobes) {
    const LtcFit f = fitLtc(ctx.runner(), lobe, n);
    for (const auto& [x, y] :
         std::vector<std::pair<int, int>>{{0, 0}, {0, n - 1}, {1, n - 1}, {n - 1, 0}, {n - 1, n - 1}}) {
      const size_t t = static_cast<size_t>(y) * n + x;
      if (f.e[t] < kLtcNegligibleE) continue;
      const LtcDistance d = ltcDistanceReference(lobe, n, f.store, f.e, t);
      StressPoint p =
          stressPoint("ltc distance, " + lobe.name() + " 8x8",
                      "r=" + fmtG(ltcRoughness(x, n)) + " mu=" + fmtG(ltcMu(y, n)), f.tv[t], d.tv, f.tvErr[t], d.err);
      p.limit = "a distance in [0, 1]";
      p.limitMet = p.finite && f.tv[t] >= 0 && f.tv[t] <= 1;
      out.push_back(p);
    }
  }
  std::fprintf(stderr, "stress: %zu points, ltc corners\n", out.size());
}

}  // namespace brdfbake
