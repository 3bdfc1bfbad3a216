#include "tables/ltc/ltc_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/material.h"
#include "common/models.h"
#include "tables/error_model.h"
#include "tables/ladder.h"
#include "tables/ltc/ltc_reference.h"

namespace brdfbake {

namespace {
// kernels/integrate/ltc_fit.h's lobe kinds
constexpr int kLobeSpecular = 0, kLobeDiffuse = 1;
constexpr int kOutPlanes = 12;  // kernels/ltc.cl ltc_fit_row
// The program a lobe's fits run in: its pair's, or for a diffuse model (which ignores the pair) the
// default pair's.
std::pair<int, int> programPair(const LtcLobeSpec& l) {
  return l.isDiffuse() ? std::pair<int, int>{NDF_GGX, GAF_SMITH_CORRELATED} : std::pair<int, int>{l.ndf, l.gaf};
}
double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

std::string LtcLobeSpec::name() const {
  return isDiffuse() ? diffuseNames()[diffuse] : ndfNames()[ndf] + "_" + gafNames()[gaf];
}

double ltcRoughness(int x, int n) { return n > 1 ? static_cast<double>(x) / (n - 1) : 0.0; }

double ltcMu(int y, int n) {
  const double t = n > 1 ? static_cast<double>(y) / (n - 1) : 0.0;
  return std::max(1.0 - t * t, std::cos(kLtcMaxTheta));
}

double ltcDiffuseParam(int diffuse, double r) {
  const DiffuseAxis ax = diffuseAxis(diffuse);
  return ax.lo + (ax.hi - ax.lo) * r;
}

bool ltcMeasuredInDouble(const LtcLobeSpec& lobe, int x, int y, int n) {
  if (lobe.isDiffuse()) return false;
  const double r = std::max(ltcRoughness(x, n), std::sqrt(kLtcMinAlpha));
  return 0x1p-24 / (r * r * ltcMu(y, n)) > kLtcFloatRho;
}

namespace {
// Whether the fit's texel (x, y) with magnitude e has its distance measured in double on the host
// (remeasureInDouble) rather than by the kernel: a lobe too narrow for float, and not negligible.
bool remeasured(const LtcLobeSpec& lobe, float e, int x, int y, int n) {
  return e >= kLtcNegligibleE && ltcMeasuredInDouble(lobe, x, y, n);
}
}  // namespace

namespace {
// The roughness the lobe of row x is fitted at: alpha = r^2 floored at kLtcMinAlpha (the kernel's
// LTC_MIN_ALPHA), so that E and B describe the lobe fitted.
double fittedRoughness(const LtcLobeSpec& lobe, int x, int n) {
  const double r = ltcRoughness(x, n);
  return lobe.isDiffuse() ? r : std::max(r, std::sqrt(kLtcMinAlpha));
}

// E and B at every texel: the hemisphere integrators (one launch of every point) for a pair, the
// diffuse albedo rule on the host in double for a diffuse model (its Fresnel moment is 0: engines
// scale the diffuse lobe by its albedo alone).
void magnitudes(KernelRunner& runner, const LtcLobeSpec& lobe, int n, LtcFit& f) {
  const size_t texels = static_cast<size_t>(n) * n;
  f.e.assign(texels, 0);
  f.b.assign(texels, 0);
  f.eBound.assign(texels, 0);
  if (lobe.isDiffuse()) {
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        double err = 0;
        const double e =
            brdf64::diffuse_albedo(lobe.diffuse, ltcDiffuseParam(lobe.diffuse, ltcRoughness(x, n)), ltcMu(y, n), &err);
        const size_t at = static_cast<size_t>(y) * n + x;
        f.e[at] = static_cast<float>(e);
        f.eBound[at] = err + std::fabs(e) * 6e-8;  // and the rounding to float
      }
    return;
  }
  std::vector<cl_float4> nodes;
  nodes.reserve(texels);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      nodes.push_back({{static_cast<float>(ltcMu(y, n)), static_cast<float>(fittedRoughness(lobe, x, n)),
                        static_cast<float>(HEMI_BAKE_TARGET), 0.0f}});
  std::vector<std::vector<float>> p = runner.hemisphereNodes(lobe.ndf, lobe.gaf, nodes);
  // E's claim: the quadrature's estimate plus the kernel's float arithmetic, as the albedo table's
  // (tables/error_model.h; without it E at r = 1, mu = 0.129 was 1.8e-7 below the reference
  // against a claim of 9.1e-8)
  const FloatModel fm = hemiFloatModel(lobe.ndf, lobe.gaf);
  for (size_t t = 0; t < texels; ++t) {
    f.e[t] = p[0][t];
    f.b[t] = p[3][t];
    f.eBound[t] = p[1][t] + floatArithmeticError(std::max(std::fabs(p[0][t]), std::fabs(p[3][t])), fm);
  }
}

// The per-row arguments every LTC kernel takes after its buffers: roughness, 1/k_p, the lobe.
struct RowArgs {
  float r, invKp;
  int kind, diffuse;
  float dparam;
};
RowArgs rowArgs(const LtcLobeSpec& lobe, int x, int n) {
  const double r = fittedRoughness(lobe, x, n);
  RowArgs a;
  a.r = static_cast<float>(r);
  a.invKp = lobe.isDiffuse() ? 0.0f : static_cast<float>(brdf64::brdf_params(lobe.ndf, lobe.gaf, r).inv_kp);
  a.kind = lobe.isDiffuse() ? kLobeDiffuse : kLobeSpecular;
  a.diffuse = lobe.diffuse;
  a.dparam = lobe.isDiffuse() ? static_cast<float>(ltcDiffuseParam(lobe.diffuse, ltcRoughness(x, n))) : 0.0f;
  return a;
}

// The distances of the texels whose lobe is too narrow for float (ltcMeasuredInDouble), measured
// again by the device's estimator (ltc_tv: the same points and shifts) in double on the host.
void remeasureInDouble(const LtcLobeSpec& lobe, int n, const std::vector<float> (&store)[4],
                       const std::vector<float>& e, const LtcBudget& budget, std::vector<float>& tv,
                       std::vector<float>& err, std::vector<float>& below) {
  std::vector<size_t> at;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const size_t t = static_cast<size_t>(y) * n + x;
      if (remeasured(lobe, e[t], x, y, n)) at.push_back(t);
    }
  ladder::onTwoThreads(at.size(), [&](size_t k) {
    const size_t t = at[k];
    const brdf64::LtcLobe L = ltcTexelLobe(lobe, static_cast<int>(t % n), static_cast<int>(t / n), n, e[t]);
    const brdf64::Ltc l = brdf64::ltc_from_stored(store[0][t], store[1][t], store[2][t], store[3][t]);
    double out[3];
    brdf64::ltc_tv(&L, l, budget.finalPoints, budget.shifts, out);
    tv[t] = static_cast<float>(out[0]);
    err[t] = static_cast<float>(out[1]);
    below[t] = static_cast<float>(out[2]);
  });
}

// The texels whose estimate exceeds 1, their distance taken from the reference quadrature instead
// (tables/ltc/ltc_reference.h, 0.01 to 0.6 s each). The sheen's sliver lobes need it: charlie +
// charlie-smith at 64^2, r = 1/63, mu = 0.123 was estimated at 1.46 (true 0.996). Taking every
// texel whose shifts spread over 0.01 as well cost charlie + none 1216 texels and 475 s. Returns
// how many.
int refineByReference(const LtcLobeSpec& lobe, int n, const std::vector<float> (&store)[4], const std::vector<float>& e,
                      std::vector<float>& tv, std::vector<float>& err) {
  std::vector<size_t> at;
  for (size_t t = 0; t < tv.size(); ++t)
    if (e[t] >= kLtcNegligibleE && tv[t] > 1) at.push_back(t);
  ladder::onTwoThreads(at.size(), [&](size_t k) {
    const size_t t = at[k];
    const LtcDistance d = ltcDistanceReference(lobe, n, store, e, t);
    tv[t] = static_cast<float>(d.tv);
    err[t] = static_cast<float>(d.err);
  });
  return static_cast<int>(at.size());
}
}  // namespace

double ltcMagnitudeShare(float e, double eBound) { return e >= kLtcNegligibleE ? 0.5 * eBound / e : 0.0; }

LtcFit fitLtc(KernelRunner& runner, const LtcLobeSpec& lobe, int n, const LtcBudget& budget) {
  LtcFit f;
  f.n = n;
  auto t0 = std::chrono::steady_clock::now();
  magnitudes(runner, lobe, n, f);
  f.magnitudeSeconds = seconds(t0);
  const size_t texels = static_cast<size_t>(n) * n;
  for (auto& s : f.store) s.assign(texels, 0);
  f.tv.assign(texels, 0);
  f.tvErr.assign(texels, 0);
  f.below.assign(texels, 0);
  f.evals.assign(texels, 0);
  std::vector<float> mus(n);
  for (int y = 0; y < n; ++y) mus[y] = static_cast<float>(ltcMu(y, n));
  const auto [ndf, gaf] = programPair(lobe);
  // a row of the kernel is one roughness (a column x of the table) over every view y
  std::vector<float> prev, e(n);
  t0 = std::chrono::steady_clock::now();
  runner.progress("rows", 0, n);
  for (int x = n - 1; x >= 0; --x) {
    for (int y = 0; y < n; ++y) e[y] = f.e[static_cast<size_t>(y) * n + x];
    // the texels remeasureInDouble measures: the kernel leaves their distance to it
    std::vector<float> inDouble(n);
    for (int y = 0; y < n; ++y) inDouble[y] = remeasured(lobe, e[y], x, y, n) ? 1.0f : 0.0f;
    const RowArgs a = rowArgs(lobe, x, n);
    std::vector<std::vector<float>> out = runner.launch(
        ProgramKey::Ltc, ndf, gaf, "ltc_fit_row", n,
        {LaunchArg::output(static_cast<size_t>(kOutPlanes) * n), LaunchArg::input(prev), LaunchArg::input(mus),
         LaunchArg::input(e), LaunchArg::input(inDouble), LaunchArg::of(n), LaunchArg::of(prev.empty() ? 0 : 1),
         LaunchArg::of(a.r), LaunchArg::of(a.invKp), LaunchArg::of(a.kind), LaunchArg::of(a.diffuse),
         LaunchArg::of(a.dparam), LaunchArg::of(budget.fitPoints), LaunchArg::of(budget.evals),
         LaunchArg::of(budget.polishEvals), LaunchArg::of(budget.finalPoints), LaunchArg::of(budget.shifts)});
    const std::vector<float>& o = out[0];
    prev.assign(o.begin(), o.begin() + 4 * n);
    for (int y = 0; y < n; ++y) {
      const size_t at = static_cast<size_t>(y) * n + x;
      for (int k = 0; k < 4; ++k) f.store[k][at] = o[static_cast<size_t>(4 + k) * n + y];
      f.tv[at] = o[static_cast<size_t>(8) * n + y];
      f.tvErr[at] = o[static_cast<size_t>(9) * n + y];
      f.below[at] = o[static_cast<size_t>(10) * n + y];
      f.evals[at] = o[static_cast<size_t>(11) * n + y];
    }
    runner.progress("rows", n - x, n);
  }
  remeasureInDouble(lobe, n, f.store, f.e, budget, f.tv, f.tvErr, f.below);
  f.byReference = refineByReference(lobe, n, f.store, f.e, f.tv, f.tvErr);
  for (size_t t = 0; t < texels; ++t) {
    f.tvErr[t] += static_cast<float>(ltcMagnitudeShare(f.e[t], f.eBound[t]));
    // a distance is at most 1, and refineByReference replaces estimates above it; should one remain,
    // it is off by at least the excess
    if (f.tv[t] > 1) f.tvErr[t] = std::max(f.tvErr[t], f.tv[t] - 1.0f);
  }
  f.seconds = seconds(t0);
  return f;
}

std::vector<std::vector<float>> measureLtc(KernelRunner& runner, const LtcLobeSpec& lobe, int n,
                                           const std::vector<float> (&store)[4], const std::vector<float>& e,
                                           const LtcBudget& budget) {
  const size_t texels = static_cast<size_t>(n) * n;
  for (const auto& s : store)
    if (s.size() != texels) throw Error(kExitSoftware, "internal: measureLtc takes n x n entries per plane");
  std::vector<std::vector<float>> res(3, std::vector<float>(texels, 0));
  std::vector<float> mus(n), col(4 * static_cast<size_t>(n)), ec(n);
  for (int y = 0; y < n; ++y) mus[y] = static_cast<float>(ltcMu(y, n));
  const auto [ndf, gaf] = programPair(lobe);
  for (int x = 0; x < n; ++x) {
    for (int y = 0; y < n; ++y) {
      const size_t at = static_cast<size_t>(y) * n + x;
      for (int k = 0; k < 4; ++k) col[static_cast<size_t>(k) * n + y] = store[k][at];
      ec[y] = e[at];
    }
    const RowArgs a = rowArgs(lobe, x, n);
    std::vector<std::vector<float>> out =
        runner.launch(ProgramKey::Ltc, ndf, gaf, "ltc_measure_row", n,
                      {LaunchArg::output(3 * static_cast<size_t>(n)), LaunchArg::input(col), LaunchArg::input(mus),
                       LaunchArg::input(ec), LaunchArg::of(n), LaunchArg::of(a.r), LaunchArg::of(a.invKp),
                       LaunchArg::of(a.kind), LaunchArg::of(a.diffuse), LaunchArg::of(a.dparam),
                       LaunchArg::of(budget.finalPoints), LaunchArg::of(budget.shifts)});
    for (int y = 0; y < n; ++y)
      for (int k = 0; k < 3; ++k) res[k][static_cast<size_t>(y) * n + x] = out[0][static_cast<size_t>(k) * n + y];
  }
  remeasureInDouble(lobe, n, store, e, budget, res[0], res[1], res[2]);
  refineByReference(lobe, n, store, e, res[0], res[1]);
  return res;
}

}  // namespace brdfbake
