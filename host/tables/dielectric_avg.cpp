#include "tables/dielectric_avg.h"

#include <algorithm>
#include <cmath>

#include "common/brdf_host.h"

namespace brdfbake {

// Derivation. E_X,avg = int_0^1 2 mu E_X(mu) dmu (Kulla and Conty 2017). E(mu) is smooth except
//  - at the critical cosine mu_c = sqrt(1 - eta^2) (eta < 1): as r -> 0, E_R -> F(mu) with F's
//    square-root kink there (TIR sets in), smoothed over a width ~ alpha for alpha > 0;
//  - at mu = eta (eta < 1), where the critical angle's theta_h break theta_o + acos(mu_c) reaches
//    the horizon (sin theta_o = mu_c): without a break there the rescaled estimates below fall up
//    to 10.9 times under the error at r = 1, eta = 1/1.5 and 0.4;
//  - at mu -> 0: E_T of smith-correlated behaves like mu^Lambda_o (btdf.h), a non-integer power,
//    and within mu ~ alpha the Smith G1(i) changes, a layer whose poles lie that close to the real
//    axis: one panel over [0, 1/2] samples it with two nodes and misses 1.5e-7 of E_R,avg (beckmann
//    + smith, r = 0.03, eta = 1.5) under a |K15 - G7| of 4.7e-8, so a break at 16 alpha starts the
//    rule there, as hemisphere.h's average does (host/cl/runner_avg.cpp).
// So the rule splits [0, 1] at mu_c, eta and 16 alpha and maps every panel [a, b] by the smoothstep
// mu = a + (b - a) y^2 (3 - 2y), which turns square-root ends into smooth ones and squeezes nodes
// towards both ends; each panel is GK15 in y (value K15; estimate |K15 - G7| rescaled as QUADPACK's
// qk15 does, gk_error, except in the two layers where E is smooth only on the scale alpha: panels
// starting below 16 alpha, and panels of the critical cosine's break starting within 16 alpha above
// it, keep |K15 - G7|). In that second layer E_R is F's square root, smoothed over ~alpha, which a
// panel from mu_c sees as a feature near its end that GK15 does not resolve; rescaled, its
// estimate falls 32 and 24 times below its error (ggx + smith-correlated, r =
// 0.0625, eta = 0.898: error 2.8e-7, estimate 8.9e-9; r = 0.2, eta = 0.6: 1.1e-7 against 4.8e-9).
// Panels are then halved in y where their estimate is largest (the ones within a factor 4 of the
// worst, all at once) until the entry's bound is under the target; the nodes thus grade towards the
// breaks and 0 as E demands, per (r, eta). Bound of each lobe: the sum of the panels' estimates plus
// sum_k w_k 2 mu_k err(mu_k) (the node bounds); of E_R,avg + E_T,avg, the two summed. The nodes come
// back from the device in double, unrounded. Measured against the same rule run tight (nodes to
// 2e-9, entries to 1e-8; docs/rough-glass.md has the figures and commands): every value within its
// bound. The bare |K15 - G7| with a target of 6e-6 would claim 30 times the error.
namespace {
constexpr int kMaxPanels = 48, kMaxRounds = 24;

struct Panel {
  double a, b, y0, y1;
  double k[2] = {0, 0}, d[2] = {0, 0}, inner[2] = {0, 0};  // K15, K15 - G7, node bounds
  double e[2] = {0, 0};                                    // the rule's estimate of each lobe
  // what the panel adds to the bound of E_R,avg + E_T,avg, the larger of the entry's three values
  double err() const { return e[0] + e[1] + inner[0] + inner[1]; }
};

// mu and its weight dmu/dy times the half-width of node m of a panel.
void node(const Panel& p, int m, double* mu, double* w) {
  double y = p.y0 + (p.y1 - p.y0) * 0.5 * (brdf64::GK15_XL[m] + 1);
  *mu = p.a + (p.b - p.a) * y * y * (3 - 2 * y);
  *w = 0.5 * (p.y1 - p.y0) * (p.b - p.a) * 6 * y * (1 - y);
}
}  // namespace

double dielectricCriticalMu(double eta) { return eta < 1 ? std::sqrt((1 - eta) * (1 + eta)) : -1; }

DielectricAverages dielectricAverages(const DielectricEval& eval, const std::vector<double>& r,
                                      const std::vector<double>& eta, double target,
                                      std::function<void(double, double)> progress) {
  const size_t n = r.size();
  std::vector<std::vector<Panel>> panels(n);
  std::vector<std::vector<size_t>> fresh(n);  // panels whose nodes are still to be evaluated
  std::vector<double> mc(n);
  for (size_t j = 0; j < n; ++j) {
    mc[j] = dielectricCriticalMu(eta[j]);
    std::vector<double> br = {0.0};
    if (mc[j] > 0 && mc[j] < 1) br.push_back(mc[j]);
    if (mc[j] > 0 && eta[j] < 1) br.push_back(eta[j]);  // sin theta_i = sqrt(1 - eta^2): mu = eta
    // the layer mu ~ alpha where G1(i) changes (hemisphere.h's average has the same panel)
    double layer = 16 * r[j] * r[j];
    if (layer > 0 && layer < 0.25 && (mc[j] <= 0 || layer < 0.5 * mc[j])) br.push_back(layer);
    std::sort(br.begin(), br.end());
    br.push_back(1.0);
    for (size_t k = 0; k + 1 < br.size(); ++k) {
      panels[j].push_back({br[k], br[k + 1], 0.0, 1.0});
      fresh[j].push_back(k);
    }
  }
  DielectricAverages out;
  out.nodes.assign(n, 0);
  for (int round = 0;; ++round) {
    if (progress) {  // entries with no panel left to evaluate: the rest refine in this round
      size_t settled = 0;
      for (size_t j = 0; j < n; ++j) settled += fresh[j].empty();
      progress(static_cast<double>(settled), static_cast<double>(n));
    }
    DielectricPoints pts;
    for (size_t j = 0; j < n; ++j)
      for (size_t q : fresh[j])
        for (int m = 0; m < 15; ++m) {
          double mu, w;
          node(panels[j][q], m, &mu, &w);
          pts.mu.push_back(mu);
          pts.r.push_back(r[j]);
          pts.eta.push_back(eta[j]);
        }
    if (pts.mu.empty()) break;
    DielectricValues v = eval(pts);
    size_t at = 0;
    for (size_t j = 0; j < n; ++j) {
      for (size_t q : fresh[j]) {
        Panel& p = panels[j][q];
        double wf[2][15];
        for (int m = 0; m < 15; ++m, ++at) {
          double mu, w;
          node(p, m, &mu, &w);
          double f[2] = {2 * mu * v.er[at], 2 * mu * v.et[at]}, b[2] = {v.br[at], v.bt[at]};
          for (int l = 0; l < 2; ++l) {
            wf[l][m] = w * f[l];
            p.k[l] += brdf64::GK15_WKL[m] * w * f[l];
            p.d[l] += brdf64::GK15_WDL[m] * w * f[l];  // WDL: Kronrod minus Gauss weights
            p.inner[l] += brdf64::GK15_WKL[m] * w * 2 * mu * b[l];
          }
        }
        // rescaled (gk_error) where E(mu) is analytic on and near the panel; |K15 - G7| on the two
        // layers of width 16 alpha where it is not: above mu = 0 (E_T goes as mu^Lambda_o, and the
        // Smith G1(i) changes within mu ~ alpha, as in hemisphere.h's average, host/cl/runner_avg.cpp),
        // and above the critical cosine (F's square root there, smoothed over ~alpha)
        const double muLo = p.a + (p.b - p.a) * p.y0 * p.y0 * (3 - 2 * p.y0), layer = 16 * r[j] * r[j];
        const bool sharp = muLo >= layer && !(p.a == mc[j] && muLo - mc[j] < layer);
        for (int l = 0; l < 2; ++l) p.e[l] = sharp ? brdf64::diel_gk_error(p.d[l], p.k[l], wf[l]) : std::fabs(p.d[l]);
      }
      out.nodes[j] += static_cast<int>(fresh[j].size()) * 15;
      fresh[j].clear();
    }
    if (round == kMaxRounds) break;
    // halve (in y) the panels within a factor 4 of the worst, where the entry is above target
    for (size_t j = 0; j < n; ++j) {
      auto& ps = panels[j];
      double total = 0, worst = 0, inner = 0;
      for (const Panel& p : ps) {
        total += p.err();
        worst = std::max(worst, p.err());
        inner += p.inner[0] + p.inner[1];
      }
      // halving cannot lower the nodes' own share: once the panels' estimates are an eighth of it,
      // more nodes would not move the bound, which then stays above the target (honest, not tight)
      if (total <= target || total - inner <= inner / 8) continue;
      size_t count = ps.size();
      for (size_t q = 0; q < count && ps.size() < kMaxPanels; ++q) {
        if (ps[q].err() < 0.25 * worst) continue;
        double ym = 0.5 * (ps[q].y0 + ps[q].y1);
        Panel right{ps[q].a, ps[q].b, ym, ps[q].y1};
        ps[q] = Panel{ps[q].a, ps[q].b, ps[q].y0, ym};
        ps.push_back(right);
        fresh[j].push_back(q);
        fresh[j].push_back(ps.size() - 1);
      }
    }
  }
  if (progress) progress(static_cast<double>(n), static_cast<double>(n));
  for (size_t j = 0; j < n; ++j) {
    double val[2] = {0, 0}, bnd[2] = {0, 0};
    for (const Panel& p : panels[j])
      for (int l = 0; l < 2; ++l) {
        val[l] += p.k[l];
        bnd[l] += p.e[l] + p.inner[l];
      }
    out.er.push_back(val[0]);
    out.et.push_back(val[1]);
    out.br.push_back(bnd[0]);
    out.bt.push_back(bnd[1]);
    out.bound.push_back(bnd[0] + bnd[1]);
  }
  return out;
}

}  // namespace brdfbake
