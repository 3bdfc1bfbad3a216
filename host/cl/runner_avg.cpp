// The average albedo E_avg(r) (KernelRunner::albedoAvg): the rule over mu (averageRule), on the
// host in double, with E at its nodes from the hemisphere kernel (KernelRunner::hemisphereNodes).
//
// Derivation. E_avg = int_0^1 2 mu E(mu) dmu (Kulla and Conty 2017). For the NDFs whose lobe
// narrows towards the normal (ggx, beckmann, blinn-phong, gaussian) E(mu) is smooth but for a
// layer of width ~alpha at the horizon, where the Smith and Schlick G1 fall from ~1 to ~mu/alpha;
// the weight 2 mu makes that layer contribute O(alpha^2). One Gauss-Kronrod 15/31 rule over [0, 1]
// meets the 8e-6 goal for every pair and r (largest bound 6.7e-6 over all of them at size 32), but
// below alpha ~ 0.01 its first nodes skip the layer and its rescaled estimate misses by up to 1.1e-7:
// there the rule starts from a GK15 panel on [0, 16 alpha] and a GK31 one on the rest
// (kernels/integrate/albedo_avg.h AVG_LAYER_ALPHA; GK15 for the layer's panel, as accurate there as
// GK31 and half the nodes, which cost the most: those entries' extra panel is 10% of the table's
// time). The panels also end at the GAF's view breaks (cook-torrance's and neumann's, brdf64::
// gaf_view_breaks), where the hemisphere estimator's theta breaks coincide and E(mu) may be
// singular. Charlie's sheen lobe grows towards grazing half-vectors as alpha falls, and its E(mu)
// changes within a layer near mu = 0 that these panels do not resolve either (a bound of 5e-5 at
// r = 1/64). So the rule is adaptive, as QUADPACK's QAG is (Piessens et al. 1983): while an entry's
// bound exceeds the goal, halve its panel with the largest bound; every round evaluates only the
// new panels' nodes, all r at once in one launch. Panel [a, b]: the nodes a + (b - a) x_k of its
// rule (x_k in [0, 1]), value (b - a) sum w_k 2 mu E, bound the rescaled |K - G| plus
// (b - a) sum w_k 2 mu err_E(mu_k). The entry's bound is the sum over its panels.
// Node k's refinement target (the estimator's second budget where its own bound exceeds it)
// shares the inner term out by weight, AVG_TARGET / (n 2 mu_k w_k), but is never below the albedo
// table's own target: every node at the refined budget would take E_avg to 8.8 to 9.0 times the
// albedo table's time instead of 0.9 (`brdfbake-bench --albedo-avg` with the target below set to 0,
// measured without the layer panels, which add ~10%: 0.90 with them, in one loaded run),
// and it is to cost no more than the albedo table it averages.
// The nodes' bounds: for the plain average of the pairs with rescaled estimates, the rule's bare
// estimates (no per-node floor) and one floor on E_avg, AVG_ERR_FLOOR, measured on the averages
// (tests/tables/microfacet/avg_rule_test.cpp); each node's own floor (1e-7 of E at the default budget) would assume
// every node misses by its worst in one direction, and would make up two thirds of the default
// pair's quadrature claim (1e-7 of 1.7e-7; the float model and the stored rounding are the rest).
// The entry's claim here is the quadrature's, plus the one rounding of the double sum to float,
// known exactly (|float(sum) - sum|, at most half an ulp); the float arithmetic of the nodes is
// tables/error_model.h's avgFloatArithmeticError.
#include <algorithm>
#include <cmath>

#include "cl/avg_rule.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/models.h"

namespace brdfbake {

namespace {
constexpr int kMaxPanels = 32;  // per entry; the halving stops there (the bound says how far it got)

// A panel's rule on [0, 1]: GK31 (kernels/integrate/albedo_avg.h), or GK15 (quadrature.h, mapped
// from [-1, 1]) for the horizon layer's panel (albedo_avg.h avg_first_break).
struct AvgRule {
  int n;
  double x(int i) const { return n == AVG_NODES ? brdf64::AVG_MU[i] : 0.5 * (1 + brdf64::GK15_XL[i]); }
  double wk(int i) const { return n == AVG_NODES ? brdf64::AVG_WK[i] : 0.5 * brdf64::GK15_WKL[i]; }
  double wd(int i) const { return n == AVG_NODES ? brdf64::AVG_WD[i] : 0.5 * brdf64::GK15_WDL[i]; }
};
constexpr AvgRule kGk31{AVG_NODES}, kGk15{15};

struct AvgPanel {
  double a, b;
  AvgRule rule = kGk31;
  double k = 0, d = 0, inner = 0;  // Kronrod, Kronrod - Gauss, node bounds
  double resasc = 0;               // len sum w_k |f_k - mean f| (QUADPACK's resasc)
  // sharp: gk_error's rescaling of |K - G| (where E(mu) is analytic)
  double bound(bool sharp) const { return brdf64::gk_error(std::fabs(d), resasc, sharp) + inner; }
};

// The nodes' positions, rounded to float for the device, are not the rule's: f(y_k) stands for
// f(x_k), off by f'(x_k) (x_k - y_k), |x_k - y_k| <= 2^-24 mu_k. Summed with the weights that is up
// to ~1e-8 of E_avg (measured, in double, as the rule's error changing by 5e-9 to 1.2e-8 when the
// panels move). The first-order term is added back: f' from the neighbouring nodes' secants
// (three-point formula on the uneven spacing), which is far more accurate than the term needs.
double nodeShift(const AvgPanel& p, const double* y, const double* f) {
  const int m = p.rule.n;
  double len = p.b - p.a, sum = 0;
  for (int i = 0; i < m; ++i) {
    int lo = std::max(0, i - 1), hi = std::min(m - 1, i + 1);
    double slope = 0;
    if (i > 0 && i < m - 1) {
      double h1 = y[i] - y[i - 1], h2 = y[i + 1] - y[i];
      if (h1 > 0 && h2 > 0) slope = ((f[i + 1] - f[i]) / h2 * h1 + (f[i] - f[i - 1]) / h1 * h2) / (h1 + h2);
    } else if (y[hi] > y[lo]) {
      slope = (f[hi] - f[lo]) / (y[hi] - y[lo]);
    }
    double x = p.a + len * p.rule.x(i);
    sum += len * p.rule.wk(i) * slope * (x - y[i]);
  }
  return sum;
}
}  // namespace

std::vector<AvgSum> averageRule(const std::vector<float>& rs, bool sharp, double goal, const AvgEvaluator& eval,
                                const AvgBreaks& breaks) {
  const size_t n = rs.size();
  std::vector<std::vector<AvgPanel>> panels(n);
  std::vector<std::vector<size_t>> fresh(n);
  for (size_t j = 0; j < n; ++j) {
    // the layer panel where it was measured: the rescaled estimates' pairs (tests/tables/microfacet/avg_rule_test.cpp);
    // charlie's E(mu) changes over a wider layer, left to the halving once its lobe break
    // (AvgBreaks, at small r) puts nodes in it. Then GK31 panels up to 1, ending at the GAF's view
    // breaks (brdf64::gaf_view_breaks) and those breaks
    std::vector<double> ends;
    double b = sharp ? brdf64::avg_first_break(rs[j]) : 1.0;
    if (b < 1.0) {
      panels[j].push_back(AvgPanel{0.0, b, kGk15});
      ends.push_back(b);
    } else {
      ends.push_back(0.0);
    }
    for (double x : breaks.at(rs[j]))
      if (x > ends.back() && x < 1.0) ends.push_back(x);
    ends.push_back(1.0);
    for (size_t e = 0; e + 1 < ends.size(); ++e) panels[j].push_back(AvgPanel{ends[e], ends[e + 1]});
    for (size_t q = 0; q < panels[j].size(); ++q) fresh[j].push_back(q);
  }
  std::vector<double> value, bound;
  for (;;) {
    std::vector<AvgNode> nodes;
    for (size_t j = 0; j < n; ++j)
      for (size_t q : fresh[j])
        for (int i = 0; i < panels[j][q].rule.n; ++i) {
          const AvgPanel& p = panels[j][q];
          float mu = static_cast<float>(p.a + (p.b - p.a) * p.rule.x(i));
          // AVG_TARGET / (n 2 mu w_k) at this node's mu, w_k its weight on [0, 1]: a panel's inner
          // term within AVG_TARGET times its length
          double share = brdf64::avg_target_share(p.rule.n, mu, p.rule.wk(i));
          nodes.push_back({mu, rs[j], static_cast<float>(std::max(HEMI_BAKE_TARGET, share))});
        }
    if (nodes.empty()) break;
    value.assign(nodes.size(), 0.0);
    bound.assign(nodes.size(), 0.0);
    eval(nodes, &value, &bound);
    size_t x = 0;
    for (size_t j = 0; j < n; ++j) {
      for (size_t q : fresh[j]) {
        AvgPanel& p = panels[j][q];
        double len = p.b - p.a, f[AVG_NODES], y[AVG_NODES];
        const int m = p.rule.n;
        for (int i = 0; i < m; ++i, ++x) {
          y[i] = nodes[x].mu;  // as the device evaluated it
          f[i] = 2 * y[i] * value[x];
          p.k += len * p.rule.wk(i) * f[i];
          p.d += len * p.rule.wd(i) * f[i];
          p.inner += len * p.rule.wk(i) * 2 * y[i] * bound[x];
        }
        for (int i = 0; i < m; ++i) p.resasc += len * p.rule.wk(i) * std::fabs(f[i] - p.k / len);
        p.k += nodeShift(p, y, f);
      }
      fresh[j].clear();
      double sum = 0, b = 0;
      for (const AvgPanel& p : panels[j]) {
        sum += p.k;
        b += p.bound(sharp);
      }
      if (b / std::max(1.0, std::fabs(sum)) <= goal || panels[j].size() >= static_cast<size_t>(kMaxPanels)) continue;
      auto worst = std::max_element(panels[j].begin(), panels[j].end(), [&](const AvgPanel& l, const AvgPanel& r) {
        return l.bound(sharp) < r.bound(sharp);
      });
      double mid = 0.5 * (worst->a + worst->b), hi = worst->b;
      AvgRule rule = worst->rule;
      *worst = AvgPanel{worst->a, mid, rule};
      fresh[j].push_back(static_cast<size_t>(worst - panels[j].begin()));
      panels[j].push_back(AvgPanel{mid, hi, rule});
      fresh[j].push_back(panels[j].size() - 1);
    }
  }
  std::vector<AvgSum> out(n);
  for (size_t j = 0; j < n; ++j) {
    std::sort(panels[j].begin(), panels[j].end(), [](const AvgPanel& l, const AvgPanel& r) { return l.a < r.a; });
    for (const AvgPanel& p : panels[j]) {  // in order of mu
      out[j].value += p.k;
      out[j].bound += p.bound(sharp);
    }
    out[j].panels = static_cast<int>(panels[j].size());
  }
  return out;
}

AvgBreaks avgBreaks(int ndf, int gaf, double kink) {
  double mu[GAF_MAX_VIEW_BREAKS];
  return AvgBreaks{std::vector<double>(mu, mu + brdf64::gaf_view_breaks(gaf, mu)), kink, isSheenNdf(ndf)};
}

std::vector<double> AvgBreaks::at(float r) const {
  std::vector<double> out = view;
  if (kink > 0) {
    const double alpha = static_cast<double>(r) * r, w = alpha * std::sqrt(1 - kink * kink) + alpha * alpha;
    for (double k : {0.0, 1.0, 3.0, 10.0})
      for (double x : {kink - k * w, kink + k * w})
        if (x > 0 && x < 1) out.push_back(x);
  }
  if (sheen && r < 1.0f / 64) out.push_back(16.0 * r);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

KernelTable KernelRunner::albedoAvg(int ndf, int gaf, int n, bool nodeGrid, const HemiWeight& w, float rLo, float rHi) {
  std::vector<float> rs(n);
  for (int j = 0; j < n; ++j) {  // as bake.cl's grid_coord computes it, in float
    float t = nodeGrid ? (n > 1 ? static_cast<float>(j) / static_cast<float>(n - 1) : 0.0f)
                       : (static_cast<float>(j) + 0.5f) / static_cast<float>(n);
    rs[j] = rLo + (rHi - rLo) * t;
  }
  // The rule's estimate is sharpened (brdf64::gk_error): E(mu) is analytic on each starting panel
  // (the horizon layer has its own; cook-torrance, neumann and charlie-smith's panels end at their
  // view breaks, gaf_view_breaks), except for a Fresnel weight with a critical angle (eta < 1),
  // whose E_F(mu) has a square-root kink there. Charlie's is sharpened too and halves to its
  // own goal (its E(mu) at small r rises within mu ~ 0.05 of the horizon).
  // |K - G| estimates the Gauss rule's error; rescaled, it is at most 3.1e-8 on every such pair's
  // 32-entry table, against 2.8e-6 (ggx + schlick-ggx, r = 0.05 to 0.15, where E(mu) changes on the
  // scale mu ~ alpha).
  const bool sheen = isSheenNdf(ndf);
  const bool sharp = brdf64::fresnel_kink(w.moments, w.fresnel, w.x, w.z) < 0;
  // The plain albedo of those pairs takes the nodes' bare estimates and the floor measured on E_avg
  // itself (kernels/integrate/albedo_avg.h AVG_ERR_FLOOR); the rest, every node's own floor.
  const bool bare = sharp && w.moments == HEMI_SPLIT;
  std::vector<AvgSum> sums = averageRule(
      rs, sharp, sheen ? kAvgGoalSheen : kAvgGoal,
      [&](const std::vector<AvgNode>& nodes, std::vector<double>* value, std::vector<double>* bound) {
        std::vector<cl_float4> in;
        in.reserve(nodes.size());
        for (const AvgNode& q : nodes) in.push_back({{q.mu, q.r, q.target, 0.0f}});
        std::vector<std::vector<float>> out = hemisphereNodes(ndf, gaf, in, w, bare);
        for (size_t k = 0; k < nodes.size(); ++k) (*value)[k] = out[0][k], (*bound)[k] = out[1][k];
      },
      avgBreaks(ndf, gaf, brdf64::fresnel_kink(w.moments, w.fresnel, w.x, w.z)));
  const double floor = bare ? brdf64::avg_floor(ndf, gaf) : 0.0;
  KernelTable t;
  t.width = n;
  t.height = 1;
  t.planes = {std::vector<float>(n)};
  t.err.resize(n);
  for (int j = 0; j < n; ++j) {
    const double sum = sums[j].value, scale = std::max(1.0, std::fabs(sum));
    const float stored = static_cast<float>(sum);
    t.planes[0][j] = stored;
    t.err[j] = static_cast<float>(
        (sums[j].bound + floor * std::fabs(sum) + std::fabs(static_cast<double>(stored) - sum)) / scale);
  }
  return t;
}

}  // namespace brdfbake
