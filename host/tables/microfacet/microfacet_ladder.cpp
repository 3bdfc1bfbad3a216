// The microfacet family's convergence ladders (brdfbake convergence --table splitsum|albedo|
// albedo-avg|kp), each against the independent reference (host/reference: adaptive Gauss-Kronrod
// in double in the plain angles, sharing only D with the kernels).
#include <cstdio>

#include "tables/error_model.h"
#include "tables/mc_common.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "reference/reference.h"
#include "tables/ladder.h"
#include "tables/microfacet/microfacet.h"

namespace brdfbake {

using ladder::best3;
using ladder::centre;
using ladder::now;

namespace {

// Common-practice MC: h by the NDF's own CDF (u1 -> v = -log(1 - u1), kernels/brdf/ndf.h), phi =
// pi u2 (the integrand is even in phi), the Hammersley point (k/N, radicalInverse2(k)); the estimate
// of each moment of E = (1/pi) int du w int_0^pi dphi H (kernels/integrate/hemisphere.h) is the
// mean of w H over the samples with n.i > 0. Float, as a tool or shader does it. Returns the two
// moments' means (A, B; with a Fresnel weight, B is that model's albedo), se[] their standard errors.
std::array<double, 2> mcTexel(int ndf, int gaf, const HemiWeight& hw, double mu, double r, int n, double se[2]) {
  brdf32::BrdfParams p = brdf32::hemisphere_texel_params(ndf, gaf, static_cast<float>(mu), static_cast<float>(r));
  p.moments = hw.moments;
  p.fresnel = hw.fresnel;
  p.fr_x = hw.x;
  p.fr_y = hw.y;
  p.fr_z = hw.z;
  float fm = static_cast<float>(mu), s = std::sqrt((1 - fm) * (1 + fm));
  double sum[2] = {0, 0}, sum2[2] = {0, 0};
  for (int k = 0; k < n; ++k) {
    float u1 = static_cast<float>(k) / static_cast<float>(n), u2 = mc::radicalInverse2(static_cast<std::uint32_t>(k));
    float v = -std::log1p(-u1);
    brdf32::BrdfAngle h = brdf32::ndf_angle_of_v(ndf, p, v);
    float sn = std::sqrt(h.s2), cphi = std::cos(3.14159265f * u2);
    float oh = s * sn * cphi + fm * h.c, ni = 2 * oh * h.c - fm;
    if (ni > 0 && oh > 0) {
      float fa, fb;
      brdf32::hemi_node(ndf, gaf, p, fm, s, h, sn, cphi, &fa, &fb);
      double w = brdf32::ndf_weight(ndf, p, h.c, h.s2);
      double f[2] = {w * fa, w * fb};
      for (int m = 0; m < 2; ++m) sum[m] += f[m], sum2[m] += f[m] * f[m];
    }
  }
  std::array<double, 2> mean{};
  for (int m = 0; m < 2; ++m) {
    mean[m] = sum[m] / n;
    se[m] = std::sqrt(std::max(0.0, sum2[m] / n - mean[m] * mean[m]) / n);
  }
  return mean;
}

struct Weights {
  HemiWeight hw;
  reference::Weight rw;
};

Weights weightsOf(const FresnelChoice& fc) {
  Weights w;
  if (!fc.isOne()) {
    auto [x, y] = fc.kernelParams(0);
    auto [mx, my] = fc.modelParams(0);
    w.hw = fresnelWeight(fc.model, x, y);
    w.rw = reference::Weight{reference::Weight::Fresnel, {fc.model, mx, my}};
  }
  return w;
}

// splitsum (A and B) and albedo (E, or E_F with a Fresnel model) over n x n texel centres: the
// bake's quadrature on the device at budget levels (every texel at the same level), the same rule in
// double on the host, and Monte Carlo.
Ladder hemisphereLadder(BakeContext& ctx, const BakeRequest& req, const LadderBudgets& budgets, TableKind kind, int ndf,
                        int gaf) {
  const int n = ladder::pointsPerAxis(req, 12, 2, 64, tableName(kind));
  const FresnelChoice& fc = fresnelOf(req);
  const bool split = kind == TableKind::SplitSum;
  if (split && !fc.isOne() && fc.model != FRESNEL_SCHLICK)
    throw Error(kExitUsage,
                "--fresnel: convergence of splitsum measures Schlick's split (A, B); give --table albedo "
                "for the albedo with " +
                    fresnelNames()[fc.model]);
  const Weights w = weightsOf(split ? FresnelChoice{} : fc);
  const bool weighted = w.hw.moments == HEMI_FRESNEL;
  Ladder L;
  L.table = tableName(kind) + " of " + ndfNames()[ndf] + "+" + gafNames()[gaf] +
            (split ? " (A and B)" : ", fresnel " + fc.describe()) + ", " + std::to_string(n) + "x" + std::to_string(n) +
            " texel centres";
  // the values measured per texel: A and B, or E (E_F)
  const size_t nv = split ? 2 : 1, texels = static_cast<size_t>(n) * n;
  auto pick = [&](double a, double b) -> std::array<double, 2> {
    if (split) return {a, b};
    return {weighted ? b : a + b, 0};
  };
  std::fprintf(stderr, "convergence: reference at %zu texels\n", texels);
  std::vector<double> ref(texels * nv);
  double t0 = now();
  ladder::onTwoThreads(texels, [&](size_t k) {
    reference::Moments m =
        reference::albedo(ndf, gaf, centre(static_cast<int>(k / n), n), centre(static_cast<int>(k % n), n), w.rw);
    auto v = pick(m.a, m.b);
    for (size_t c = 0; c < nv; ++c) ref[k * nv + c] = v[c];
  });
  const double refSeconds = now() - t0;

  KernelRunner& kr = ctx.runner();
  kr.prepare(KernelNeed{KernelNeed::Hemisphere, ndf, gaf});
  kr.hemisphere(ndf, gaf, n, n, false, w.hw);  // warm: the kernel's compile is not timed
  for (int level : budgets.levels) {
    std::fprintf(stderr, "convergence: quadrature level %d\n", level);
    KernelTable t;
    double secs = best3([&] { t = kr.hemisphereRange(ndf, gaf, n, n, 0, 1, 0, 1, false, w.hw, level); });
    std::vector<double> v(texels * nv), e(texels);
    for (size_t k = 0; k < texels; ++k) {
      auto x = split ? std::array<double, 2>{t.planes[0][k], t.planes[1][k]}
                     : std::array<double, 2>{weighted ? t.planes[1][k] : t.planes[2][k], 0};
      for (size_t c = 0; c < nv; ++c) v[k * nv + c] = x[c];
      // + the float arithmetic's share, as the bake claims it (tables/error_model.h)
      double scale = std::max({std::fabs(t.planes[0][k]), std::fabs(t.planes[1][k]), std::fabs(t.planes[2][k])});
      e[k] = t.err[k] + (weighted ? weightedFloatError(t.planes[1][k], t.planes[2][k], scale, ndf, gaf,
                                                       weightCancels(w.hw.fresnel))
                                  : floatArithmeticError(scale, hemiFloatModel(ndf, gaf)));
    }
    L.rungs.push_back(ladder::rung("quadrature (device, float)", "level " + std::to_string(level), secs, v, e, ref));
  }
  for (int level : budgets.levels) {
    std::fprintf(stderr, "convergence: quadrature level %d in double\n", level);
    std::vector<double> v(texels * nv), e(texels);
    double s0 = now();
    ladder::onTwoThreads(texels, [&](size_t k) {
      double mu = centre(static_cast<int>(k % n), n), r = centre(static_cast<int>(k / n), n);
      brdf64::BrdfParams p = brdf64::hemisphere_texel_params(ndf, gaf, mu, r);
      p.moments = w.hw.moments, p.fresnel = w.hw.fresnel, p.fr_x = w.hw.x, p.fr_y = w.hw.y, p.fr_z = w.hw.z;
      brdf64::HemiResult h = brdf64::hemisphere_moments(ndf, gaf, p, mu, level);
      auto x = pick(h.a, h.b);
      for (size_t c = 0; c < nv; ++c) v[k * nv + c] = x[c];
      e[k] = brdf64::hemi_rel_error(h);
    });
    L.rungs.push_back(
        ladder::rung("quadrature (host, double)", "level " + std::to_string(level), now() - s0, v, e, ref));
  }
  for (int ns : budgets.samples) {
    std::fprintf(stderr, "convergence: Monte Carlo %d samples\n", ns);
    std::vector<double> v(texels * nv), e(texels);
    double s0 = now();
    ladder::onTwoThreads(texels, [&](size_t k) {
      double se[2];
      auto m = mcTexel(ndf, gaf, w.hw, centre(static_cast<int>(k % n), n), centre(static_cast<int>(k / n), n), ns, se);
      auto x = pick(m[0], m[1]);
      auto s = split ? std::array<double, 2>{se[0], se[1]} : std::array<double, 2>{weighted ? se[1] : se[0] + se[1], 0};
      for (size_t c = 0; c < nv; ++c) {
        v[k * nv + c] = x[c];
        e[k] = std::max(e[k], 3 * s[c] / std::max(1.0, std::fabs(x[c])));
      }
    });
    L.rungs.push_back(
        ladder::rung("Monte Carlo (Hammersley, float)", std::to_string(ns) + " samples", now() - s0, v, e, ref));
  }
  double agree = 0;
  for (const Rung& r : L.rungs)
    if (r.method == "quadrature (host, double)") agree = r.error;
  L.note = "The reference (adaptive Gauss-Kronrod in double in the plain angles, host/reference) took " +
           fmt3(refSeconds) + " s for " + std::to_string(texels) +
           " texels; the finest double quadrature, another method, agrees with it "
           "to " +
           fmt3(agree) + "\n";
  return L;
}

// albedo-avg over n texel centres in r: the bake's rule (GK panels over mu, halved where the bound
// is largest, E on the device) and a plain composite Gauss-Legendre over mu of the same device E(mu)
// at rising panel counts (levels L: 2^L panels of 8 nodes), against the reference's E_avg.
Ladder avgLadder(BakeContext& ctx, const BakeRequest& req, const LadderBudgets& budgets, int ndf, int gaf) {
  const int n = ladder::pointsPerAxis(req, 6, 1, 32, "albedo-avg");
  const FresnelChoice& fc = fresnelOf(req);
  const Weights w = weightsOf(fc);
  const bool weighted = w.hw.moments == HEMI_FRESNEL;
  Ladder L;
  L.table = "albedo-avg of " + ndfNames()[ndf] + "+" + gafNames()[gaf] + ", fresnel " + fc.describe() + ", " +
            std::to_string(n) + " texel centres in r";
  std::fprintf(stderr, "convergence: reference at %d roughnesses\n", n);
  std::vector<double> ref(n);
  double t0 = now();
  ladder::onTwoThreads(
      ref.size(), [&](size_t j) { ref[j] = reference::albedoAvg(ndf, gaf, centre(static_cast<int>(j), n), w.rw); });
  const double refSeconds = now() - t0;
  KernelRunner& kr = ctx.runner();
  kr.prepare(KernelNeed{KernelNeed::Hemisphere, ndf, gaf});
  kr.albedoAvg(ndf, gaf, n, false, w.hw);  // warm
  {
    KernelTable t;
    double secs = best3([&] { t = kr.albedoAvg(ndf, gaf, n, false, w.hw); });
    std::vector<double> v(n), e(n);
    for (int j = 0; j < n; ++j) {
      v[j] = t.planes[0][j];
      e[j] = t.err[j] + avgFloatArithmeticError(std::fabs(v[j]), ndf, gaf, weighted);
    }
    L.rungs.push_back(ladder::rung("the bake's rule (device E, double sums)", "goal " + fmt3(KernelRunner::kAvgGoal),
                                   secs, v, e, ref));
  }
  std::vector<double> prev;
  for (int level : budgets.levels) {
    const int panels = 1 << level;
    // the nodes of every roughness at once, one device run
    const std::vector<ladder::Node> gl = ladder::gaussLegendreNodes(0, 1, panels);
    std::vector<cl_float4> nodes;
    for (int j = 0; j < n; ++j)
      for (const ladder::Node& x : gl)
        nodes.push_back(cl_float4{
            {static_cast<float>(x.x), static_cast<float>(centre(j, n)), static_cast<float>(HEMI_BAKE_TARGET), 0}});
    std::vector<std::vector<float>> out;
    double secs = best3([&] { out = kr.hemisphereNodes(ndf, gaf, nodes, w.hw); });
    std::vector<double> v(n), e(n);
    for (int j = 0; j < n; ++j) {
      double sum = 0, bound = 0;
      for (size_t k = 0; k < gl.size(); ++k) {
        size_t at = static_cast<size_t>(j) * gl.size() + k;
        sum += gl[k].w * 2 * gl[k].x * out[0][at];
        bound += gl[k].w * 2 * gl[k].x * out[1][at];
      }
      v[j] = sum;
      e[j] = bound + (prev.empty() ? 0 : std::fabs(v[j] - prev[j]));
    }
    prev = v;
    L.rungs.push_back(
        ladder::rung("Gauss-Legendre in mu (device E)", std::to_string(panels) + " x 8 nodes", secs, v, e, ref));
  }
  L.note =
      "The reference (E_avg = 2 int E mu dmu by adaptive Gauss-Kronrod in double over the reference's E, "
      "host/reference) took " +
      fmt3(refSeconds) + " s for " + std::to_string(n) +
      " roughnesses; a Gauss-Legendre "
      "rung's estimate is its nodes' bounds plus its change from the previous rung\n";
  return L;
}

// k_p over n texel centres in r: the bake's rule on the device, and composite Gauss-Legendre in
// theta in double (levels L: 4^L panels of 8 nodes), against the reference's k_p.
Ladder kpLadder(BakeContext& ctx, const BakeRequest& req, const LadderBudgets& budgets, int ndf) {
  const int n = ladder::pointsPerAxis(req, 8, 1, 64, "kp");
  Ladder L;
  L.table = "kp of " + ndfNames()[ndf] + ", " + std::to_string(n) + " texel centres in r";
  std::vector<double> ref(n);
  double t0 = now();
  for (int j = 0; j < n; ++j) ref[j] = reference::kp(ndf, centre(j, n));
  const double refSeconds = now() - t0;
  KernelRunner& kr = ctx.runner();
  kr.prepare(KernelNeed{KernelNeed::Kp, ndf, 0});
  kr.kp(ndf, n, false);  // warm
  {
    KernelTable t;
    double secs = best3([&] { t = kr.kp(ndf, n, false); });
    std::vector<double> v(n), e(n);
    for (int j = 0; j < n; ++j) {
      v[j] = t.planes[0][j];
      e[j] = t.err[j] + floatArithmeticError(std::fabs(v[j]), kKpFloat);
    }
    L.rungs.push_back(ladder::rung("the bake's rule (device, float)", "fixed", secs, v, e, ref));
  }
  std::vector<double> prev;
  for (int level : budgets.levels) {
    const int panels = 1 << (2 * level);
    std::vector<double> v(n);
    double secs = best3([&] {
      for (int j = 0; j < n; ++j) {
        brdf64::BrdfParams p{};
        p.r = centre(j, n);
        p.alpha = p.r * p.r;
        v[j] = ladder::gaussLegendre(
            [&](double th) {
              double s = std::sin(th), c = std::cos(th);
              return 2 * M_PI * brdf64::ndf_p(ndf, p, c, s * s) * c * s;
            },
            0, M_PI / 2, panels);
      }
    });
    const std::vector<double> e = ladder::changeFrom(prev, v);
    prev = v;
    L.rungs.push_back(
        ladder::rung("Gauss-Legendre in theta (host, double)", std::to_string(panels) + " x 8 nodes", secs, v, e, ref));
  }
  L.note =
      "The reference (k_p = 2 pi int p(theta) cos sin dtheta by adaptive Gauss-Kronrod in double, panels graded on "
      "the lobe, host/reference) took " +
      fmt3(refSeconds) +
      " s; a Gauss-Legendre rung's estimate is its change from "
      "the previous rung\n";
  return L;
}

}  // namespace

Ladder microfacetLadder(BakeContext& ctx, const BakeRequest& req, TableKind kind, const LadderBudgets& budgets) {
  if (req.ndfs.size() != 1 || req.gafs.size() != 1)
    throw Error(kExitUsage, "convergence measures one pair: give one --ndf and one --gaf");
  if (req.diffuse >= 0)
    throw Error(kExitUsage,
                "--diffuse: convergence measures the specular estimators (the diffuse albedo has one budget)");
  if (fresnelOf(req).channels() != 1)
    throw Error(kExitUsage, "convergence takes one value per Fresnel parameter, not R,G,B");
  const int ndf = req.ndfs[0], gaf = req.gafs[0];
  if (kind == TableKind::Kp) {
    if (req.fresnel) throw Error(kExitUsage, "--fresnel: --table kp has no Fresnel");
    return kpLadder(ctx, req, budgets, ndf);
  }
  if (gaf == GAF_NONE) throw Error(kExitUsage, "--gaf none: E grows like 1/mu at grazing; pick a GAF");
  if (kind == TableKind::AlbedoAvg) return avgLadder(ctx, req, budgets, ndf, gaf);
  return hemisphereLadder(ctx, req, budgets, kind, ndf, gaf);
}

}  // namespace brdfbake
