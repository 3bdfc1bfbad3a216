// The rough dielectric's average albedos over mu (--table dielectric-avg; docs/MODELS.md "Rough
// dielectric"): E_X,avg(r, eta) = 2 int_0^1 E_X(mu, r, eta) mu dmu for X = R, T, by an adaptive
// panel rule in mu whose nodes are chosen per (r, eta). E(mu) is evaluated in batches by a callback
// (the device's bake_dielectric_points, or the host's double estimator in tests).
#pragma once
#include <functional>
#include <vector>

namespace brdfbake {

// One batch: E_R, E_T and each lobe's bound (absolute) at points (mu[k], r[k], eta[k]).
struct DielectricPoints {
  std::vector<double> mu, r, eta;
};
struct DielectricValues {
  std::vector<double> er, et, br, bt;
};
using DielectricEval = std::function<DielectricValues(const DielectricPoints&)>;

// The averages at (r[j], eta[j]): values, bounds per lobe (the panels' estimates plus the node
// bounds' weighted sum) and of their sum E_R,avg + E_T,avg (both lobes' bounds summed, the largest),
// and how many E(mu) evaluations each took.
struct DielectricAverages {
  std::vector<double> er, et, br, bt, bound;
  std::vector<int> nodes;
};

// The bound the rule aims at per entry: that of E_R,avg + E_T,avg, the larger of its three values.
// A table's brdf.error adds each entry's own rounding to float (at most 2^-25 = 3.0e-8 below 1) and
// the double arithmetic's 1e-9 (tables/dielectric/dielectric_bake.cpp), about 1.1e-7 in all.
constexpr double kDielectricAvgTarget = 8e-8;
// The target of each node's E_R and E_T (kernels/integrate/dielectric.h). The nodes' bounds enter an
// entry's weighted by 2 mu dmu and run ~10 times their errors, so a tighter target buys little:
// 15 entries of a 16^2 table (target 8e-8) take 25 s at 1e-7 and 31 s at 2.5e-8, the largest
// entry bound 6.5e-8 and 6.7e-8 (a scratch run).
constexpr float kDielectricAvgNodeTarget = 1e-7f;

// The critical cosine sqrt(1 - eta^2) for eta < 1 (where E(mu) has its TIR kink), else -1.
double dielectricCriticalMu(double eta);

DielectricAverages dielectricAverages(const DielectricEval& eval, const std::vector<double>& r,
                                      const std::vector<double>& eta, double target = kDielectricAvgTarget,
                                      std::function<void(double settled, double total)> progress = {});

}  // namespace brdfbake
