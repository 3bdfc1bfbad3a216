// The average albedo's rule (host/cl/avg_rule.h) and its floors, measured on the averages.
//
// E_avg's bound is the rule's own (the outer panels' rescaled |K - G| plus the nodes' bare rule
// estimates, weighted) plus AVG_ERR_FLOOR (and, with a tabulated Lambda, AVG_SMITH_TABLE_ERR_*)
// times E_avg: kernels/integrate/albedo_avg.h. This test runs the very rule the bake runs, with E at
// its nodes from the same estimator in double on the host (the budget chosen by the same rule in
// double, which near the threshold can differ from the device's float choice; the float nodes the
// device would get), so that what it measures is the quadrature
// alone (the float arithmetic is tests/tables/microfacet/avg_float_test.cpp's), against the independent reference
// (host/reference, adaptive Boost GK in double on other coordinates). It checks every such pair
// (the rescaled estimate's) at r across the horizon-layer range and the rest,
// and prints the largest miss, (error - rule bound) / E_avg, per pair; BRDFBAKE_AVG_SWEEP=1 runs
// every r of 32- and 64-entry tables and a 33-entry node grid instead (how the floors were set:
// ~35 minutes on two cores; BRDFBAKE_AVG_GAFS=0,2 restricts it to those GAF ids). The reference's
// values at the default r come from tests/data/reference_values.txt (tests/reference_cache.h):
// computing them all takes 96% of this test's time, about 7 minutes of CPU for the four NDFs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cl/avg_rule.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/models.h"
#include "reference/reference.h"
#include "host_avg_rule.h"
#include "reference_cache.h"
#include "test_device.h"
#include "doc_figures.h"

namespace brdfbake {
namespace {
using brdf64::real;  // for the RC() of albedo_avg.h's constants

using testing_avg::hostRule;

const bool sweeping = [] {
  const char* e = std::getenv("BRDFBAKE_AVG_SWEEP");
  return e && std::string(e) == "1";
}();

// every r of 32- and 64-entry tables and a 33-entry node grid
std::vector<float> fullSweepR() {
  std::vector<float> rs;
  for (int n : {32, 64})
    for (int j = 0; j < n; ++j) rs.push_back((static_cast<float>(j) + 0.5f) / static_cast<float>(n));
  for (int j = 0; j <= 32; ++j) rs.push_back(static_cast<float>(j) / 32.0f);
  return rs;
}

std::vector<float> sweepR() {
  if (sweeping) return fullSweepR();
  std::vector<float> rs;
  // the horizon layer's range (alpha < 0.01: r < 0.1) and the largest misses of the sweep (r = 7/64
  // and 1/8, just above it), the rest sparsely, and the ends (8 r: 11 make this the suite's longest
  // test, 2.5 minutes for ggx alone on a loaded machine)
  for (int j : {1, 5, 7, 8, 21, 63}) rs.push_back(static_cast<float>(j) / 64.0f);
  for (float r : {0.0f, 1.0f}) rs.push_back(r);
  return rs;
}

// E_avg by the bake's rule at each r against the reference (computed afresh when `fresh`, else the
// kept values): each within the rule's bound plus its floor. Returns the largest miss beyond the
// rule's bound, (error - rule bound) / max(1, E_avg), what the floors cover, and the r it is at.
std::pair<double, float> pairMiss(int ndf, int gaf, const std::vector<float>& rs, bool fresh) {
  std::vector<AvgSum> got = hostRule(ndf, gaf, rs);
  std::vector<double> ref(rs.size());
  std::vector<std::thread> threads;
  for (size_t t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      for (size_t j = t; j < rs.size(); j += 2) {
        auto compute = [&] { return reference::albedoAvg(ndf, gaf, rs[j]); };
        ref[j] =
            fresh ? compute()
                  : testing_ref::cached1(
                        testing_ref::keyOf("albedoAvg " + ndfNames()[ndf] + " " + gafNames()[gaf], {rs[j]}), compute);
      }
    });
  for (std::thread& t : threads) t.join();
  double worst = 0;
  float at = 0;
  for (size_t j = 0; j < rs.size(); ++j) {
    const double v = got[j].value, err = std::fabs(v - ref[j]), scale = std::max(1.0, std::fabs(v));
    EXPECT_LE(err, got[j].bound + brdf64::avg_floor(ndf, gaf) * std::fabs(v))
        << ndfNames()[ndf] << "+" << gafNames()[gaf] << " r " << rs[j] << " E_avg " << v << " ref " << ref[j];
    const double miss = (err - got[j].bound) / scale;
    if (miss > worst) worst = miss, at = rs[j];
  }
  return {worst, at};
}

class AvgRule : public ::testing::TestWithParam<int> {};

// Every pair of the NDF at the suite's 8 r (which hold the full sweep's largest misses, at r = 7/64
// and 1/8) or, with BRDFBAKE_AVG_SWEEP=1, at the sweep's. docs/accuracy.md quotes the suite's largest
// miss per NDF.
TEST_P(AvgRule, BoundHoldsWithTheFloorsMeasuredOnTheAverage) {
  const int ndf = GetParam();
  const std::vector<float> rs = sweepR();
  double worstMiss = 0, worstTable = 0;
  // BRDFBAKE_AVG_GAFS=2,4 (GAF ids, kernels/brdf/gaf.h): those GAFs only, to sweep a few pairs
  std::vector<int> only;
  if (const char* e = std::getenv("BRDFBAKE_AVG_GAFS")) {
    std::istringstream in(e);
    for (std::string id; std::getline(in, id, ',');) {
      ASSERT_TRUE(!id.empty() && id.find_first_not_of("0123456789") == std::string::npos)
          << "BRDFBAKE_AVG_GAFS: comma-separated GAF ids (kernels/brdf/gaf.h), got \"" << e << "\"";
      only.push_back(std::stoi(id));
    }
  }
  std::string said;
  for (int gaf = 0; gaf < GAF_COUNT; ++gaf) {
    if (!pairSupported(ndf, gaf)) continue;
    if (!only.empty() && std::find(only.begin(), only.end(), gaf) == only.end()) continue;
    const bool tabulated = brdf64::avg_model_error(ndf, gaf) > 0;
    const auto [miss, at] = pairMiss(ndf, gaf, rs, sweeping);
    double& worst = tabulated ? worstTable : worstMiss;
    worst = std::max(worst, miss);
    testing_docs::say(said, "%s+%s: E_avg off its rule's bound by at most %.2e (r = %.4f)%s\n", ndfNames()[ndf].c_str(),
                      gafNames()[gaf].c_str(), miss, at, tabulated ? " (tabulated Lambda)" : "");
  }
  // the floors keep at least twice what they cover (albedo_avg.h states the margins: 2.4, 2.2)
  EXPECT_LE(2 * worstMiss, AVG_ERR_FLOOR) << ndfNames()[ndf];
  if (worstTable > 0) {
    EXPECT_LE(2 * worstTable, brdf64::avg_floor(ndf, GAF_SMITH_EXACT)) << ndfNames()[ndf];
  }
  testing_docs::say(said, "%s: largest miss %.2e (floor %.1e, %.2f times it)", ndfNames()[ndf].c_str(), worstMiss,
                    static_cast<double>(AVG_ERR_FLOOR), worstMiss > 0 ? AVG_ERR_FLOOR / worstMiss : 0.0);
  if (worstTable > 0)
    testing_docs::say(said, "; with the tabulated Lambda %.2e (floor + table %.1e)", worstTable,
                      static_cast<double>(brdf64::avg_floor(ndf, GAF_SMITH_EXACT)));
  testing_docs::say(said, "\n");
  if (!sweeping && only.empty()) testing_docs::expectPagesQuote(said);
}

// The tabulated exact Lambda's share of E_avg's error (AVG_SMITH_TABLE_ERR_*): blinn-phong's and the
// gaussian's exact-Smith pairs at every r of 32- and 64-entry tables and a 33-entry node grid,
// against the reference computed afresh (the suite's 8 r do not reach it). About 16 minutes on two
// cores: AvgRuleSweep.TheTabulatedLambdasShareIsThePages, behind the `sweep` label.
TEST(AvgRuleSweep, DISABLED_TabulatedLambdaShare) {
  std::string said;
  for (int ndf : {NDF_BLINN_PHONG, NDF_GAUSSIAN}) {
    double worst = 0;
    for (int gaf : {GAF_SMITH_EXACT, GAF_SMITH_CORRELATED_EXACT}) {
      ASSERT_GT(brdf64::avg_model_error(ndf, gaf), 0) << ndfNames()[ndf] << "+" << gafNames()[gaf];
      const auto [miss, at] = pairMiss(ndf, gaf, fullSweepR(), true);
      testing_docs::say(said, "%s+%s: E_avg off its rule's bound by at most %.2e (r = %.4f)\n", ndfNames()[ndf].c_str(),
                        gafNames()[gaf].c_str(), miss, at);
      worst = std::max(worst, miss);
    }
    EXPECT_LE(2 * worst, brdf64::avg_floor(ndf, GAF_SMITH_EXACT)) << ndfNames()[ndf];
    testing_docs::say(said, "%s: the tabulated Lambda's largest share %.2e (floor + table %.1e)\n",
                      ndfNames()[ndf].c_str(), worst, static_cast<double>(brdf64::avg_floor(ndf, GAF_SMITH_EXACT)));
  }
  testing_docs::expectPagesQuote(said);
}

INSTANTIATE_TEST_SUITE_P(MicrofacetNdfs, AvgRule,
                         ::testing::Values(NDF_GGX, NDF_BECKMANN, NDF_BLINN_PHONG, NDF_GAUSSIAN),
                         [](const ::testing::TestParamInfo<int>& info) {
                           std::string s = ndfNames()[info.param];
                           std::replace(s.begin(), s.end(), '-', '_');
                           return s;
                         });

// The bake's device rule agrees with the host's (same panels, the float arithmetic apart), and its
// entries claim the floors: the default pair's table, entry by entry.
TEST(AvgRuleDevice, DeviceTableMatchesTheHostRule) {
  const int n = 32;
  int gaf = GAF_SMITH_CORRELATED;
  KernelTable t = testing_device::runner().albedoAvg(NDF_GGX, gaf, n, false);
  std::vector<float> rs(n);
  for (int j = 0; j < n; ++j) rs[j] = (static_cast<float>(j) + 0.5f) / static_cast<float>(n);
  std::vector<AvgSum> host = hostRule(NDF_GGX, gaf, rs);
  for (int j = 0; j < n; ++j) {
    EXPECT_NEAR(t.planes[0][j], host[j].value, 4e-7) << "r " << rs[j];
    // the claim holds the rule's bound (computed from float node bounds) and the floor
    EXPECT_GE(t.err[j], 0.5 * (host[j].bound + AVG_ERR_FLOOR * host[j].value)) << "r " << rs[j];
    EXPECT_LE(t.err[j], 2.0 * (host[j].bound + AVG_ERR_FLOOR * host[j].value) + 6e-8) << "r " << rs[j];
    EXPECT_EQ(host[j].panels, brdf64::avg_first_break(rs[j]) < 1 ? 2 : 1) << "r " << rs[j];
  }
}

}  // namespace
}  // namespace brdfbake
