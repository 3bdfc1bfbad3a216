// The average albedo's rule over mu, apart from where E comes from (host/cl/runner_avg.cpp): the
// bake takes E at the nodes from the device (KernelRunner::albedoAvg), tests/tables/microfacet/avg_rule_test.cpp from
// the same estimator in double, to measure what the rule's own bound misses.
#pragma once
#include <functional>
#include <vector>

namespace brdfbake {

struct AvgNode {
  float mu, r, target;  // where E is wanted, and the refinement target of its estimator
};
// Fills value[k] and bound[k] (E at nodes[k] and its absolute bound) for every node.
using AvgEvaluator =
    std::function<void(const std::vector<AvgNode>& nodes, std::vector<double>* value, std::vector<double>* bound)>;

struct AvgSum {
  double value = 0;  // E_avg, in double
  double bound = 0;  // the rule's bound: outer estimates plus the weighted node bounds
  int panels = 0;
};

// Where an entry's first panels end: the views where the GAF's E(mu) is singular
// (brdf64::gaf_view_breaks), and for a Fresnel weight with a critical cosine oc (eta < 1), where
// E_F(mu) bends: oc, and oc +- 1, 3 and 10 lobe widths w = alpha sqrt(1 - oc^2) + alpha^2 (the
// spread of o.h over the lobe) at the entry's r. Without them, at eta = 0.9999, r = 3/64 the
// rule's |K - G| saw 2.9e-6 where the average was off by 1.4e-5
// (tests/tables/microfacet/fresnel_edge_test.cpp, AverageAlbedoAtTheStiffCorner).
// For the sheen NDF (charlie), below r = 1/64, also mu = 16 r: charlie's lobe lies within
// ~sqrt(alpha) = r of grazing half-vectors, so E(mu) lives on mu < ~10 r (2 mu E largest at
// mu -> 0). Without the break the GK31 panel over [0, 1], whose first node is mu = 0.001, sees
// none of it once r < ~8e-5: at r = 1/16384 (an 8192-entry table's first entry) charlie + none's
// E_avg came out 0.00078 with a bound of 2.7e-11 where it is 1.0
// (tests/tables/microfacet/sheen_test.cpp, AlbedoAvgHoldsItsLobeAtTheSmallestR). From r = 1/64 on
// the lobe reaches past mu = 1/4, where the panel's own nodes sample it (at r = 1/64 the average
// meets the reference to 2.2e-9, AlbedoAvgMeetsTheGoalAtTheSmallestRoughness), so those entries,
// every 32-entry table's among them, keep their panels.
struct AvgBreaks {
  std::vector<double> view;
  double kink = -1;    // oc, or -1
  bool sheen = false;  // the sheen NDF's lobe break
  std::vector<double> at(float r) const;
};
AvgBreaks avgBreaks(int ndf, int gaf, double kink);

// E_avg at each r: Gauss-Kronrod panels over mu (GK31; GK15 for the horizon layer's, sharp pairs
// only: kernels/integrate/albedo_avg.h avg_first_break), halved where the bound is largest until
// it meets the goal (relative to max(1, E_avg)); sharp: |K - G| rescaled (brdf64::gk_error).
// breaks: where the first panels end (avgBreaks); no default, so that every caller runs the
// bake's rule for its GAF and weight.
std::vector<AvgSum> averageRule(const std::vector<float>& rs, bool sharp, double goal, const AvgEvaluator& eval,
                                const AvgBreaks& breaks);

}  // namespace brdfbake
