// The average albedo E_avg(r) (KernelRunner::albedoAvg): the rule over mu, on the host in double,
// with E at its nodes from the hemisphere kernel (KernelRunner::hemisphereNodes).
//
// Derivation. E_avg = int_0^1 2 mu E(mu) dmu (Kulla and Conty 2017). For the NDFs whose lobe
// narrows towards the normal (ggx, beckmann, blinn-phong, gaussian) E(mu) is smooth and the weight
// 2 mu makes the horizon layer mu ~ alpha, where E changes fastest, contribute O(alpha^2): one
// Gauss-Kronrod 15/31 rule over [0, 1] meets the target for every pair and r (largest bound
// 6.7e-6 over all of them at size 32). Charlie's sheen lobe grows towards grazing half-vectors as
// alpha falls, and E(mu) then changes within a layer of width ~alpha near mu = 0 that one rule does
// not resolve (a bound of 5e-5 at r = 1/64). So the rule is adaptive, as QUADPACK's QAG is
// (Piessens et al. 1983): start with [0, 1], and while an entry's bound exceeds the target, halve
// its panel with the largest bound; every round evaluates only the new panels' nodes, all r at
// once in one launch. Panel [a, b]: the nodes a + (b - a) x_k of kernels/integrate/albedo_avg.h's
// GK31 (x_k in [0, 1]), value (b - a) sum w_k 2 mu E, bound |K31 - G15| plus
// (b - a) sum w_k 2 mu err_E(mu_k). The entry's bound is the sum over its panels.
// Node k's refinement target (the estimator's second budget where its own bound exceeds it)
// shares the inner term out by weight, AVG_TARGET / (31 * 2 mu_k w_k), but is never below the
// albedo table's own target: refining the heavy middle nodes further than a texel of the albedo
// cost a third of the time and changed no bound by more than 5%. Every node at the refined budget
// (whose floor is 1e-9 of the value, not 1e-7) would make the default pair's claim 2.1e-7 instead
// of 3.4e-7 (true error 7.1e-8), but E_avg would take 8.8 to 9.0 times the albedo table's time
// instead of 0.9 (`brdfbake-bench --albedo-avg` with the target below set to 0), and it is to cost
// no more than the albedo table it averages (issue 7).
// The entry's claim here is the quadrature's, plus the one rounding of the double sum to float,
// known exactly (|float(sum) - sum|, at most half an ulp); the float arithmetic of the nodes is
// bake/error_model.h's avgFloatArithmeticError.
#include <algorithm>
#include <cmath>

#include "cl/runner.h"
#include "common/brdf_host.h"

namespace brdfbake {

namespace {
constexpr double kAvgGoal = KernelRunner::kAvgGoal;
constexpr int kMaxPanels = 32;     // per entry; the halving stops there (the bound says how far it got)

struct AvgPanel {
  double a, b;
  double k = 0, d = 0, inner = 0;  // K31, K31 - G15, node bounds
  double resasc = 0;                // len sum w_k |f_k - mean f| (QUADPACK's resasc)
  // sharp: gk_error's rescaling of |K31 - G15| (where E(mu) is analytic)
  double bound(bool sharp) const { return brdf64::gk_error(std::fabs(d), resasc, sharp) + inner; }
};
}  // namespace

KernelTable KernelRunner::albedoAvg(int ndf, int gaf, int n, bool nodeGrid, const HemiWeight& w, float rLo,
                                    float rHi) {
  const int m = AVG_NODES;
  std::vector<float> rs(n);
  for (int j = 0; j < n; ++j) {  // as bake.cl's grid_coord computes it, in float
    float t = nodeGrid ? (n > 1 ? static_cast<float>(j) / static_cast<float>(n - 1) : 0.0f)
                       : (static_cast<float>(j) + 0.5f) / static_cast<float>(n);
    rs[j] = rLo + (rHi - rLo) * t;
  }
  // The rule's estimate is sharpened (brdf64::gk_error) where the hemisphere estimator's is: E(mu)
  // is then analytic on [0, 1], except for a Fresnel weight with a critical angle (eta < 1), whose
  // E_F(mu) has a square-root kink there. |K31 - G15| estimates G15's error; rescaled, it is at
  // most 3.1e-8 on every such pair's 32-entry table, against 2.8e-6 (ggx + schlick-ggx, r = 0.05
  // to 0.15, where E(mu) changes on the scale mu ~ alpha).
  const bool sharp = brdf64::hemi_sharp_estimate(ndf, gaf) && brdf64::fresnel_kink(w.moments, w.fresnel, w.x) < 0;
  std::vector<std::vector<AvgPanel>> panels(n, std::vector<AvgPanel>{{0.0, 1.0}});
  std::vector<std::vector<size_t>> fresh(n, std::vector<size_t>{0});
  for (;;) {
    std::vector<cl_float4> nodes;
    for (int j = 0; j < n; ++j)
      for (size_t q : fresh[j])
        for (int i = 0; i < m; ++i) {
          const AvgPanel& p = panels[j][q];
          float mu = static_cast<float>(p.a + (p.b - p.a) * brdf64::AVG_MU[i]);
          // AVG_TARGET / (31 * 2 mu w_k) at this node's mu
          double share = brdf64::avg_node_target(i) * brdf64::AVG_MU[i] / mu;
          float target = static_cast<float>(std::max(HEMI_BAKE_TARGET, share));
          nodes.push_back({{mu, rs[j], target, 0.0f}});
        }
    if (nodes.empty()) break;
    std::vector<std::vector<float>> out = hemisphereNodes(ndf, gaf, nodes, w);
    size_t x = 0;
    for (int j = 0; j < n; ++j) {
      for (size_t q : fresh[j]) {
        AvgPanel& p = panels[j][q];
        double len = p.b - p.a, f[AVG_NODES];
        for (int i = 0; i < m; ++i, ++x) {
          double mu = nodes[x].s[0];  // as the device evaluated it
          f[i] = 2 * mu * out[0][x];
          p.k += len * brdf64::AVG_WK[i] * f[i];
          p.d += len * brdf64::AVG_WD[i] * f[i];
          p.inner += len * brdf64::AVG_WK[i] * 2 * mu * out[1][x];
        }
        for (int i = 0; i < m; ++i) p.resasc += len * brdf64::AVG_WK[i] * std::fabs(f[i] - p.k / len);
      }
      fresh[j].clear();
      double sum = 0, bound = 0;
      for (const AvgPanel& p : panels[j]) {
        sum += p.k;
        bound += p.bound(sharp);
      }
      if (bound / std::max(1.0, std::fabs(sum)) <= kAvgGoal || panels[j].size() >= static_cast<size_t>(kMaxPanels))
        continue;
      auto worst = std::max_element(panels[j].begin(), panels[j].end(),
                                    [&](const AvgPanel& l, const AvgPanel& r) { return l.bound(sharp) < r.bound(sharp); });
      double mid = 0.5 * (worst->a + worst->b), hi = worst->b;
      *worst = AvgPanel{worst->a, mid};
      fresh[j].push_back(static_cast<size_t>(worst - panels[j].begin()));
      panels[j].push_back(AvgPanel{mid, hi});
      fresh[j].push_back(panels[j].size() - 1);
    }
  }
  KernelTable t;
  t.width = n;
  t.height = 1;
  t.planes = {std::vector<float>(n)};
  t.err.resize(n);
  for (int j = 0; j < n; ++j) {
    double sum = 0, bound = 0;
    std::sort(panels[j].begin(), panels[j].end(), [](const AvgPanel& l, const AvgPanel& r) { return l.a < r.a; });
    for (const AvgPanel& p : panels[j]) {  // in order of mu
      sum += p.k;
      bound += p.bound(sharp);
    }
    const float stored = static_cast<float>(sum);
    t.planes[0][j] = stored;
    t.err[j] = static_cast<float>((bound + std::fabs(static_cast<double>(stored) - sum)) / std::max(1.0, std::fabs(sum)));
  }
  return t;
}

}  // namespace brdfbake
