// The OpenCL kernels against the independent reference (host adaptive quadrature in double), for
// every NDF/GAF pair at edge and interior points, and the honesty of their error bounds.
// Needs an OpenCL device: with none, selectDevice throws and these tests fail loudly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include "cl/device.h"
#include "tables/error_model.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/models.h"
#include "reference/reference.h"
#include "test_device.h"

namespace {
using namespace brdfbake;

using testing_device::rel;
using testing_device::runner;

constexpr double kGoal = 1e-5;  // the goal: every texel within 1e-5 of the exact integral
// The reference's own accuracy (adaptive GK31 to ~1e-11; limits from inside to ~1e-9).
constexpr double kReferenceSlack = 3e-9;
constexpr double kLimitSlack = 1e-7;

std::string pairName(int ndf, int gaf) { return ndfNames()[ndf] + "+" + gafNames()[gaf]; }

class PairTest : public ::testing::TestWithParam<std::pair<int, int>> {};

// The largest float error seen, as a fraction of the model's bound (tables/error_model.h keeps a
// margin: printed).
double gWorstFloat = 0;
std::string gWorstFloatAt;  // its pair and texel
// The rules' largest miss (true error minus the rule's own estimate, before the floor), relative to
// the value, over the pairs with sharpened estimates, per budget (default, refined): what the
// floors (HEMI_ERR_FLOOR_SHARP, HEMI_ERR_FLOOR_REFINED) cover.
double gWorstMiss[2] = {0, 0};
// Per NDF, the largest float error in units of u = 2^-24 (relative to max(1, |v|), the device against
// the same rule in double, every channel) and the largest fraction of its model's bound: what
// tables/error_model.h's per-NDF models are fitted to.
std::map<int, testing_device::FloatWorst> gWorstOfNdf;  // at: the pair of the largest in u
// The largest |lookup - reference| of a bilinear lookup in a 32x32 node table near the corner
// (NodeTableNearTheCornerReadsWhatTheInsideHolds), over every pair, and its pair.
double gWorstCornerLookup = 0;
std::string gWorstCornerLookupAt;

// After the last test of a run, the largest of each over every test that ran: a run of the whole
// binary in one process prints the figures docs/accuracy.md quotes (AccuracySweep checks them;
// ctest runs each test alone, which sees only its own).
class WholeRunMaxima : public ::testing::Environment {
 public:
  void TearDown() override {
    std::string perNdf;
    for (const auto& [ndf, w] : gWorstOfNdf) {
      char one[120];
      std::snprintf(one, sizeof one, "%s%s %.2f on %s (at most %.2f of its bound)", perNdf.empty() ? "" : ", ",
                    ndfNames()[ndf].c_str(), w.u, w.at.c_str(), w.share);
      perNdf += one;
    }
    std::printf(
        "whole run: largest float error %.2f of the float model's bound (%s); largest misses of a sharpened "
        "estimate %.2e at the default budget, %.2e at the refined one; largest float error per NDF in u: %s; "
        "a lookup in a node table near the corner, largest |lookup - reference| %.3f (%s)\n",
        gWorstFloat, gWorstFloatAt.c_str(), gWorstMiss[0], gWorstMiss[1], perNdf.c_str(), gWorstCornerLookup,
        gWorstCornerLookupAt.c_str());
  }
};
[[maybe_unused]] ::testing::Environment* const kWholeRunMaxima =
    ::testing::AddGlobalTestEnvironment(new WholeRunMaxima);

// Texel k of a hemisphere table at (mu, r) against the reference, each claim on its own:
//  - the quadrature estimate: the same rule in double on the host (both budgets, default and
//    refined), against the reference: |estimate - exact| <= its per-texel estimate;
//  - the float model: the device's float result is the double result of one of those two budgets
//    (whichever the device chose) to within floatArithmeticError of the texel's largest moment;
//  - the whole claim, as the bake makes it: |device - exact| <= device estimate + float model,
//    and <= the 1e-5 goal.
// A, B and E each, E against the reference's own E (integrated directly, not A + B).
// Returns the device's error (relative to max(1, |value|)).
double checkTexel(const KernelTable& t, size_t k, int ndf, int gaf, double mu, double r) {
  SCOPED_TRACE(pairName(ndf, gaf) + " mu=" + std::to_string(mu) + " r=" + std::to_string(r));
  reference::Moments ref = reference::albedo(ndf, gaf, r, mu);
  const double want[3] = {ref.a, ref.b, ref.e()};
  double flt[3] = {1, 1, 1};
  // the limits (mu = 0: the reference at mu = 1e-9 alpha; the corner at alpha ~ 1e-9 where the
  // kernel takes 1e-10) are approached along different paths: they agree to ~1e-7
  const double slack = mu == 0 ? kLimitSlack : kReferenceSlack;
  brdf64::BrdfParams p = brdf64::hemisphere_texel_params(ndf, gaf, mu, r);
  for (int refine : {0, 1}) {
    brdf64::HemiResult h = brdf64::hemisphere_moments(ndf, gaf, p, mu, refine);
    const double est[3] = {h.a, h.b, h.a + h.b}, bound = brdf64::hemi_rel_error(h);
    const double ruleOnly = brdf64::hemi_rel_error(brdf64::hemi_rule(ndf, gaf, p, mu, refine));
    const bool sharp = brdf64::hemi_model_error(ndf, gaf) == 0;
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(rel(est[c], want[c]), bound + slack)
          << "quadrature bound not honest, budget " << refine << ", channel "
          << "ABE"[c] << ": estimate " << est[c] << " exact " << want[c] << " bound " << bound;
      flt[c] = std::min(flt[c], rel(t.planes[c][k], est[c]));
    }
    // as the claim is made: the largest error over A, B, E against the largest estimate, per unit
    // of the floor's share of the claim (the floor times the largest |v| / max(1, |v|))
    double worstErr = 0, share = 0;
    for (int c = 0; c < 3; ++c) {
      worstErr = std::max(worstErr, rel(est[c], want[c]));
      share = std::max(share, std::fabs(est[c]) / std::max(1.0, std::fabs(est[c])));
    }
    if (sharp && mu > 0 && share > 0) gWorstMiss[refine] = std::max(gWorstMiss[refine], (worstErr - ruleOnly) / share);
  }
  double scale = 0;
  for (int c = 0; c < 3; ++c) scale = std::max(scale, std::fabs(static_cast<double>(t.planes[c][k])));
  const double arith = floatArithmeticError(scale, hemiFloatModel(ndf, gaf));
  double e = 0;
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(flt[c], arith) << "float model exceeded, channel "
                             << "ABE"[c] << ": device " << t.planes[c][k];
    gWorstOfNdf[ndf].add(flt[c], arith, pairName(ndf, gaf));
    if (flt[c] / arith > gWorstFloat) {
      gWorstFloat = flt[c] / arith;
      char where[120];
      std::snprintf(where, sizeof where, "%s, mu %.4g, r %.4g", pairName(ndf, gaf).c_str(), mu, r);
      gWorstFloatAt = where;
    }
    e = std::max(e, rel(t.planes[c][k], want[c]));
  }
  EXPECT_TRUE(std::isfinite(t.planes[2][k]));
  // (slack: the reference's own accuracy, as above)
  EXPECT_LE(e, t.err[k] + arith + slack) << "claim is not honest: value " << t.planes[2][k] << " ref " << ref.e();
  EXPECT_LE(e, kGoal) << "value " << t.planes[2][k] << " ref " << ref.e();
  return e;
}

// Node grid 9x9 (mu and r at 0, 1/8, ..., 1: the table edges) and texel centres of an 8x8 grid.
TEST_P(PairTest, HemisphereMatchesReference) {
  auto [ndf, gaf] = GetParam();
  for (bool node : {true, false}) {
    int n = node ? 9 : 8;
    KernelTable t = runner().hemisphere(ndf, gaf, n, n, node);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        double mu = node ? i / double(n - 1) : (i + 0.5) / n, r = node ? j / double(n - 1) : (j + 0.5) / n;
        if (gaf == 0 && mu == 0) continue;  // infinite; the plan refuses this grid for gaf none
        checkTexel(t, static_cast<size_t>(j) * n + i, ndf, gaf, mu, r);
      }
  }
  std::printf(
      "%s: largest float error so far %.2f of the float model's bound; largest miss of a sharpened "
      "estimate so far %.2e of the value at the default budget (floor %.0e), %.2e at the refined one "
      "(floor %.0e)\n",
      pairName(ndf, gaf).c_str(), gWorstFloat, gWorstMiss[0], double(brdf64::hemi_floor(0)), gWorstMiss[1],
      double(brdf64::hemi_floor(1)));
}

// E_avg at r = 0 (the mirror limit, exact: 2 int_0^1 E(mu, 0) mu dmu with E(mu, 0) = G at the
// mirror configuration, docs/MODELS.md), at r = 0.5 and r = 1 against the reference.
double exactMirrorAverage(int gaf) {
  switch (gaf) {
    case GAF_IMPLICIT:
      return 0.5;  // 2 int mu^3
    case GAF_NEUMANN:
      return 2.0 / 3.0;  // 2 int mu^2
    case GAF_ASHIKHMIN_PREMOZE:
      return 8 * std::log(2.0) - 5;  // 2 int mu^2/(2 - mu)
    case GAF_SCHLICK_GGX_DIRECT:     // 2 int mu (8 mu/(7 mu + 1))^2
      return 128.0 / 2401.0 * (9.625 + 9 * std::log(2.0));
    default:
      return 1.0;  // G = 1 at the mirror configuration
  }
}

TEST_P(PairTest, AverageAlbedoMatchesReference) {
  auto [ndf, gaf] = GetParam();
  KernelTable t = runner().albedoAvg(ndf, gaf, 3, true);  // r = 0, 0.5, 1
  for (int j = 0; j < 3; ++j) {
    double r = j / 2.0;
    double ref = r == 0 ? exactMirrorAverage(gaf) : reference::albedoAvg(ndf, gaf, r);
    if (r == 0) {
      EXPECT_NEAR(reference::albedoAvg(ndf, gaf, 0), ref, 1e-10) << "the reference's mirror limit";
    }
    double e = rel(t.planes[0][j], ref);
    SCOPED_TRACE(pairName(ndf, gaf) + " r=" + std::to_string(r));
    // the claim as the bake makes it (bake.cpp Arith::HemiAvg): the estimate, the nodes' float
    // error averaged, the host's double sum rounded to float (and the reference's accuracy)
    double v = t.planes[0][j];
    double claim = t.err[j] + avgFloatArithmeticError(v, ndf, gaf);
    EXPECT_LE(e, claim + kReferenceSlack) << "claim is not honest: " << t.planes[0][j] << " ref " << ref;
    EXPECT_LE(e, kGoal) << t.planes[0][j] << " ref " << ref;
  }
}

// The GAFs these reference sweeps cover: all but the exact-Smith ones, whose reference Lambda is
// itself an adaptive integral per direction (a 1025-node cache per (NDF, r)), which makes every
// sweep here take minutes per pair. Those two are checked against the reference in
// tests/smith_exact_test.cpp (Lambda, weak furnace, the device's albedo at nodes) and for
// finiteness below; for ggx and beckmann they are smith and smith-correlated exactly.
constexpr int kReferenceSweepGafs = GAF_SMITH_CORRELATED + 1;

std::vector<std::pair<int, int>> allPairs() {
  std::vector<std::pair<int, int>> v;
  // (the sheen NDF's pairs are checked against their own, incident-direction reference: sheen_test.cpp)
  for (int n = 0; n < NDF_COUNT; ++n)
    for (int g = 0; g < kReferenceSweepGafs; ++g)
      if (pairSupported(n, g) && !isSheenNdf(n)) v.push_back({n, g});
  return v;
}

INSTANTIATE_TEST_SUITE_P(AllPairs, PairTest, ::testing::ValuesIn(allPairs()),
                         [](const ::testing::TestParamInfo<std::pair<int, int>>& info) {
                           std::string s = ndfNames()[info.param.first] + "_" + gafNames()[info.param.second];
                           std::replace(s.begin(), s.end(), '-', '_');
                           return s;
                         });

TEST(Kp, KernelMatchesClosedFormsAndReference) {
  double worstKp = 0;
  for (int ndf = 0; ndf < 4; ++ndf) {
    int n = 9;
    KernelTable t = runner().kp(ndf, n, true);
    for (int j = 0; j < n; ++j) {
      double r = j / double(n - 1), a = r * r;
      double exact = ndf == 3 ? (r == 0 ? 0 : reference::kp(ndf, r)) : 3.14159265358979323846 * a * a;
      EXPECT_LE(rel(t.planes[0][j], exact), 3e-7) << ndfNames()[ndf] << " r=" << r;  // float rounding
      EXPECT_LE(rel(t.planes[0][j], exact), t.err[j] + floatArithmeticError(t.planes[0][j], kKpFloat));
      if (exact > 0)
        worstKp = std::max(worstKp, rel(t.planes[0][j], exact) / floatArithmeticError(t.planes[0][j], kKpFloat));
    }
  }
  std::printf("k_p: largest error %.2f of the float model's bound\n", worstKp);
}

// The table edges at full resolution: every edge texel of a 128x128 texel-centre table, where
// mu = 1/256 (grazing) and r = 1/256 (alpha = 1.5e-5; Blinn-Phong e ~ 4e9).
TEST_P(PairTest, EveryEdgeTexelOfA128TableMatchesReference) {
  auto [ndf, gaf] = GetParam();
  const int n = 128;
  KernelTable t = runner().hemisphere(ndf, gaf, n, n, false);
  double worst = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (i != 0 && j != 0 && i != n - 1 && j != n - 1) continue;
      worst = std::max(worst, checkTexel(t, static_cast<size_t>(j) * n + i, ndf, gaf, (i + 0.5) / n, (j + 0.5) / n));
    }
  std::printf(
      "%s + %s: largest edge-texel error %.2e; largest miss of a sharpened estimate so far %.2e of the value "
      "(default budget), %.2e (refined)\n",
      ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), worst, gWorstMiss[0], gWorstMiss[1]);
}

// Stiff parameters: Blinn-Phong exponents past 1e9 (r = 1/128 and below) at grazing views, every
// GAF. Finite everywhere, and the stiffest texels of a 64x64 table match the reference.
TEST(Stiff, BlinnPhongHugeExponentsAndGrazingViewsMatchReference) {
  const int n = 64;
  for (int gaf = 0; gaf < GAF_COUNT; ++gaf) {
    if (!pairSupported(NDF_BLINN_PHONG, gaf)) continue;
    KernelTable t = runner().hemisphere(NDF_BLINN_PHONG, gaf, n, n, false);
    for (size_t k = 0; k < t.planes[2].size(); ++k)
      ASSERT_TRUE(std::isfinite(t.planes[0][k]) && std::isfinite(t.planes[1][k]) && std::isfinite(t.err[k]));
    if (gaf >= kReferenceSweepGafs) continue;  // finite; the reference comparison is smith_exact_test's
    for (int i : {0, 1, n / 2, n - 1})         // mu = 1/128 (e = 2 128^4 ~ 5e8 at r = 1/128), 3/128, 1/2, 1 - 1/128
      checkTexel(t, static_cast<size_t>(i), NDF_BLINN_PHONG, gaf, (i + 0.5) / n, 0.5 / n);
  }
}

}  // namespace

namespace {
// A shader's bilinear lookup in a 32x32 node table near the corner, at (mu = 1e-6, r = 0.01),
// against the reference there: the corner holds the limit along the mu = 0 edge, so the lookup
// follows the table's inside (when the corner held 0, ggx + smith-correlated read 0.31 for 0.998).
TEST_P(PairTest, NodeTableNearTheCornerReadsWhatTheInsideHolds) {
  auto [ndf, gaf] = GetParam();
  if (gaf == GAF_NONE) return;  // infinite at mu = 0: node grids refuse it
  const int n = 32;
  KernelTable t = runner().hemisphere(ndf, gaf, n, n, true);
  const double mu = 1e-6, r = 0.01;
  double x = mu * (n - 1), y = r * (n - 1);  // node grid: texel i at i/(n-1)
  int i = static_cast<int>(x), j = static_cast<int>(y);
  double fx = x - i, fy = y - j;
  auto at = [&](int ii, int jj) { return static_cast<double>(t.planes[2][static_cast<size_t>(jj) * n + ii]); };
  double lookup =
      (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) + fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
  double ref = reference::albedo(ndf, gaf, r, mu).e();
  // and the corner texel itself, the limit along the mu = 0 edge (docs/MODELS.md quotes it)
  std::printf("%s: lookup %.4f, reference %.4f, corner %.4f\n", pairName(ndf, gaf).c_str(), lookup, ref, at(0, 0));
  EXPECT_NEAR(lookup, ref, 0.03) << pairName(ndf, gaf);  // the whole run prints the largest (formats.md)
  if (std::fabs(lookup - ref) > gWorstCornerLookup) {
    gWorstCornerLookup = std::fabs(lookup - ref);
    gWorstCornerLookupAt = pairName(ndf, gaf);
  }
}
}  // namespace

namespace {
// A plan of many pairs runs their integrators in one shared program (the pair a kernel argument,
// host/cl/runner.h Sharing); it must give every table the same bits as the pair's own program, so
// that what a file holds does not depend on what else was baked with it. 15 pairs cover every
// NDF and every GAF; each table kind the two programs hold (split sum and a Fresnel albedo on
// texel centres and node edges, albedo-avg, k_p).
TEST(SharedProgram, SameBitsAsEachPairsOwnProgram) {
  KernelRunner own(selectDevice("").device), shared(selectDevice("").device);
  own.setSharing(KernelRunner::Sharing::PerPair);
  shared.setSharing(KernelRunner::Sharing::Shared);
  const std::vector<std::pair<std::string, std::string>> pairs = {{"ggx", "none"},
                                                                  {"ggx", "cook-torrance"},
                                                                  {"ggx", "smith-correlated"},
                                                                  {"ggx", "smith"},
                                                                  {"beckmann", "implicit"},
                                                                  {"beckmann", "neumann"},
                                                                  {"beckmann", "schlick-beckmann"},
                                                                  {"blinn-phong", "kelemen"},
                                                                  {"blinn-phong", "smith-exact"},
                                                                  {"blinn-phong", "schlick-ggx-direct"},
                                                                  {"gaussian", "ashikhmin-premoze"},
                                                                  {"gaussian", "smith-correlated-exact"},
                                                                  {"gaussian", "schlick-ggx"},
                                                                  {"charlie", "charlie-smith"},
                                                                  {"charlie", "neubelt"}};
  HemiWeight glass;
  glass.moments = HEMI_FRESNEL;
  glass.fresnel = FRESNEL_DIELECTRIC;
  glass.x = 1.5f;
  auto same = [](const KernelTable& a, const KernelTable& b, const std::string& what) {
    ASSERT_EQ(a.planes.size(), b.planes.size()) << what;
    for (size_t c = 0; c < a.planes.size(); ++c)
      EXPECT_EQ(0, std::memcmp(a.planes[c].data(), b.planes[c].data(), a.planes[c].size() * sizeof(float)))
          << what << ", plane " << c;
    EXPECT_EQ(0, std::memcmp(a.err.data(), b.err.data(), a.err.size() * sizeof(float))) << what << ", bounds";
  };
  std::vector<KernelNeed> needs;
  for (const auto& [n, g] : pairs)
    for (KernelNeed::Kernel k : {KernelNeed::Hemisphere, KernelNeed::Kp}) needs.push_back({k, ndfId(n), gafId(g)});
  own.prepareAll(needs);
  shared.prepareAll(needs);
  for (const auto& [n, g] : pairs) {
    int ndf = ndfId(n), gaf = gafId(g);
    std::string name = n + "+" + g;
    same(own.hemisphere(ndf, gaf, 6, 5, false), shared.hemisphere(ndf, gaf, 6, 5, false), name + " split sum");
    if (gaf != GAF_NONE)
      same(own.hemisphere(ndf, gaf, 5, 5, true), shared.hemisphere(ndf, gaf, 5, 5, true), name + " node grid");
    if (!isSheenNdf(ndf))
      same(own.hemisphere(ndf, gaf, 4, 4, false, glass), shared.hemisphere(ndf, gaf, 4, 4, false, glass),
           name + " dielectric albedo");
    same(own.albedoAvg(ndf, gaf, 4, false), shared.albedoAvg(ndf, gaf, 4, false), name + " albedo-avg");
    same(own.kp(ndf, 4, false), shared.kp(ndf, 4, false), name + " k_p");
  }
  EXPECT_FALSE(own.sharedProgramBuilt());
  EXPECT_TRUE(shared.sharedProgramBuilt());
}
}  // namespace

namespace {
// A bake's runner keeps its launches' results (KernelRunner::setReuse): a launch that repeats one,
// the GAF through gaf_canonical, returns the same bits as running it would (ggx + smith-exact's
// tables are ggx + smith's), and one with any other argument runs.
TEST(KernelReuse, RepeatsReturnWhatRunningGives) {
  KernelRunner plain(selectDevice("").device), kept(selectDevice("").device);
  kept.setReuse(true);
  auto same = [](const KernelTable& a, const KernelTable& b) {
    if (a.planes.size() != b.planes.size() || a.err != b.err) return false;
    for (size_t c = 0; c < a.planes.size(); ++c)
      if (std::memcmp(a.planes[c].data(), b.planes[c].data(), a.planes[c].size() * sizeof(float)) != 0) return false;
    return true;
  };
  for (int ndf : {NDF_GGX, NDF_BECKMANN}) {
    KernelTable first = kept.hemisphere(ndf, GAF_SMITH, 6, 5, false);
    EXPECT_TRUE(same(first, plain.hemisphere(ndf, GAF_SMITH, 6, 5, false)));
    EXPECT_TRUE(
        same(kept.hemisphere(ndf, GAF_SMITH_EXACT, 6, 5, false), plain.hemisphere(ndf, GAF_SMITH_EXACT, 6, 5, false)));
    EXPECT_TRUE(same(kept.albedoAvg(ndf, GAF_SMITH_CORRELATED_EXACT, 4, false),
                     plain.albedoAvg(ndf, GAF_SMITH_CORRELATED_EXACT, 4, false)));
  }
  // other arguments run: another size, another weight, a tabulated exact Lambda
  EXPECT_TRUE(
      same(kept.hemisphere(NDF_GGX, GAF_SMITH, 5, 5, false), plain.hemisphere(NDF_GGX, GAF_SMITH, 5, 5, false)));
  HemiWeight glass;
  glass.moments = HEMI_FRESNEL;
  glass.fresnel = FRESNEL_DIELECTRIC;
  glass.x = 1.5f;
  EXPECT_TRUE(same(kept.hemisphere(NDF_GGX, GAF_SMITH, 6, 5, false, glass),
                   plain.hemisphere(NDF_GGX, GAF_SMITH, 6, 5, false, glass)));
  EXPECT_FALSE(
      same(kept.hemisphere(NDF_GGX, GAF_SMITH, 6, 5, false, glass), kept.hemisphere(NDF_GGX, GAF_SMITH, 6, 5, false)));
  kept.hemisphere(NDF_BLINN_PHONG, GAF_SMITH, 6, 5, false);
  EXPECT_TRUE(same(kept.hemisphere(NDF_BLINN_PHONG, GAF_SMITH_EXACT, 6, 5, false),
                   plain.hemisphere(NDF_BLINN_PHONG, GAF_SMITH_EXACT, 6, 5, false)));
  EXPECT_FALSE(same(plain.hemisphere(NDF_BLINN_PHONG, GAF_SMITH, 6, 5, false),
                    plain.hemisphere(NDF_BLINN_PHONG, GAF_SMITH_EXACT, 6, 5, false)));
}

cl_float4 nodeAt(float mu, float r, float target) { return {{mu, r, target, 0.0f}}; }

// hemisphereNodes keeps each point's results and launches only the points it has not seen: a request
// that overlaps earlier ones (the albedo table's probes repeat most of the split sum's) returns,
// point for point, the bits a runner without reuse computes for it.
TEST(KernelReuse, NodesOverlappingEarlierOnesGiveTheSameBits) {
  const cl::Device device = selectDevice("").device;
  KernelRunner fresh(device), reusing(device);
  reusing.setReuse(true);
  std::vector<cl_float4> first, second;
  for (int k = 1; k <= 12; ++k) first.push_back(nodeAt(k / 13.0f, 0.05f * k, 1.0f));
  // the second request: points of the first in another order, a repeated one, new points, and a
  // point of the first with another target (another point)
  second = {first[7],
            nodeAt(0.011f, 0.3f, 1.0f),
            first[2],
            first[2],
            nodeAt(0.5f, 0.02f, 1.0f),
            first[11],
            nodeAt(first[4].s[0], first[4].s[1], 3e-7f),
            first[0]};
  for (const HemiWeight& w : {HemiWeight{}, HemiWeight{HEMI_FRESNEL, FRESNEL_SCHLICK, 0.04f, 0.0f}}) {
    const auto seen = reusing.hemisphereNodes(NDF_GGX, GAF_SMITH_CORRELATED, first, w);
    const auto got = reusing.hemisphereNodes(NDF_GGX, GAF_SMITH_CORRELATED, second, w);
    const auto want = fresh.hemisphereNodes(NDF_GGX, GAF_SMITH_CORRELATED, second, w);
    ASSERT_EQ(got.size(), 4u);
    ASSERT_EQ(want.size(), 4u);
    for (int q = 0; q < 4; ++q) {
      ASSERT_EQ(got[q].size(), second.size());
      EXPECT_EQ(0, std::memcmp(got[q].data(), want[q].data(), second.size() * sizeof(float))) << "plane " << q;
    }
    // a point's values do not depend on the launch it came in: the first request's own
    EXPECT_EQ(got[0][0], seen[0][7]);
    EXPECT_EQ(got[2][2], seen[2][2]);
    // the same request again, every point known: the same bits, bare kept apart from not bare
    EXPECT_EQ(reusing.hemisphereNodes(NDF_GGX, GAF_SMITH_CORRELATED, second, w), got);
    const auto bare = reusing.hemisphereNodes(NDF_GGX, GAF_SMITH_CORRELATED, second, w, true);
    EXPECT_EQ(bare, fresh.hemisphereNodes(NDF_GGX, GAF_SMITH_CORRELATED, second, w, true));
  }
}

// The sqrt(mu) x axis (Unity HDRP's newer FGD lookup): texel i of n holds the table at mu = u^2,
// u = (i + 0.5)/n (texel centres) or i/(n - 1) (nodes), the same bits as a one-point evaluation
// there, and the r axis is unchanged.
TEST(Grid, SqrtMuAxisHoldsTheTableAtMuSquared) {
  KernelRunner& k = runner();
  for (bool nodes : {false, true}) {
    const int n = 5;
    KernelTable t = k.hemisphere(NDF_GGX, GAF_SMITH_CORRELATED, n, n, nodes, {}, true);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        float u = nodes ? static_cast<float>(i) / static_cast<float>(n - 1) : (static_cast<float>(i) + 0.5f) / n;
        float r = nodes ? static_cast<float>(j) / static_cast<float>(n - 1) : (static_cast<float>(j) + 0.5f) / n;
        float mu = u * u;
        KernelTable p = k.hemisphereRange(NDF_GGX, GAF_SMITH_CORRELATED, 1, 1, mu, mu, r, r, true);
        size_t x = static_cast<size_t>(j) * n + i;
        EXPECT_EQ(t.planes[0][x], p.planes[0][0]) << "A at u=" << u << " r=" << r << (nodes ? " (nodes)" : "");
        EXPECT_EQ(t.planes[1][x], p.planes[1][0]) << "B at u=" << u << " r=" << r;
      }
  }
}
}  // namespace
