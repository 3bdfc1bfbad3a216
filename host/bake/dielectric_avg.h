// The rough dielectric's average albedos over mu (--table dielectric-avg; docs/MODELS.md "Rough
// dielectric"): E_X,avg(r, eta) = 2 int_0^1 E_X(mu, r, eta) mu dmu for X = R, T, by an adaptive
// panel rule in mu whose nodes are chosen per (r, eta). E(mu) is evaluated in batches by a callback
// (the device's bake_dielectric_points, or the host's double estimator in tests).
#pragma once
#include <functional>
#include <vector>

namespace brdfbake {

// One batch: E_R, E_T and their bound (absolute, the two lobes' estimates summed) at points (mu[k], r[k], eta[k]).
struct DielectricPoints {
  std::vector<double> mu, r, eta;
};
struct DielectricValues {
  std::vector<double> er, et, bound;
};
using DielectricEval = std::function<DielectricValues(const DielectricPoints&)>;

// The averages at (r[j], eta[j]): values and bounds (|K15 - G7| of every panel plus the
// node bounds' weighted sum), and how many E(mu) evaluations each took.
struct DielectricAverages {
  std::vector<double> er, et, bound;
  std::vector<int> nodes;
};

// Bound the rule aims at per entry (both lobes); the table's brdf.error adds the allowances. Above
// the nodes' own share (their bounds, ~1e-7 at the nodes' target), which no halving reduces.
constexpr double kDielectricAvgTarget = 1.5e-7;

// The critical cosine sqrt(1 - eta^2) for eta < 1 (where E(mu) has its TIR kink), else -1.
double dielectricCriticalMu(double eta);

DielectricAverages dielectricAverages(const DielectricEval& eval, const std::vector<double>& r,
                                      const std::vector<double>& eta, double target = kDielectricAvgTarget);

}  // namespace brdfbake
