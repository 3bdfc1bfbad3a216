// The bake's rule for the average albedo (host/cl/avg_rule.h) with E in double at the nodes it asks
// for, bare estimates as the bake's kernel gives them: what tests compare the device's tables and
// the reference with (tests/tables/microfacet/avg_rule_test.cpp, tests/tables/microfacet/sheen_test.cpp).
#pragma once
#include <vector>

#include "cl/avg_rule.h"
#include "cl/runner.h"
#include "common/brdf_host.h"

namespace brdfbake::testing_avg {

// sheenLobeBreak false: without the sheen NDF's break at 16 r (AvgBreaks), to show what it is for.
inline std::vector<AvgSum> hostRule(int ndf, int gaf, const std::vector<float>& rs,
                                    double goal = KernelRunner::kAvgGoal, bool sheenLobeBreak = true) {
  AvgBreaks breaks = avgBreaks(ndf, gaf, -1);
  breaks.sheen = breaks.sheen && sheenLobeBreak;
  return averageRule(
      rs, true, goal,
      [&](const std::vector<AvgNode>& nodes, std::vector<double>* value, std::vector<double>* bound) {
        for (size_t k = 0; k < nodes.size(); ++k) {
          double mu = nodes[k].mu;
          brdf64::BrdfParams p = brdf64::hemisphere_texel_params(ndf, gaf, mu, nodes[k].r);
          brdf64::HemiResult h = brdf64::hemisphere_moments_chosen(ndf, gaf, p, mu, -1, nodes[k].target, 1);
          (*value)[k] = h.a + h.b;
          (*bound)[k] = h.err_a + h.err_b;
        }
      },
      breaks);
}

}  // namespace brdfbake::testing_avg
