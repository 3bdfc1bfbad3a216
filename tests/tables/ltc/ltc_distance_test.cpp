// The LTC family's distances and magnitudes against independent references: E and B against the
// reference albedo, the reference distance (tables/ltc/ltc_reference.h) against a sphere
// quadrature, and each texel's stated distance and claim against the reference where they are
// hardest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/brdf_host.h"
#include "common/models.h"
#include "doc_figures.h"
#include "ltc_test_util.h"
#include "reference/reference.h"
#include "tables/ladder.h"
#include "tables/ltc/ltc_fit.h"
#include "tables/ltc/ltc_reference.h"
#include "test_device.h"

using namespace brdfbake;
using brdfbake::testing_device::runner;
using brdfbake::testing_ltc::sphereIntegral;

namespace {

// E and B (ltc2's R and G) against the independent reference's albedo and Fresnel moment at the
// lobe the texel fits (its float view and roughness), within their claim, on a 16^2 table's first
// two and last roughness rows and its first and last views. The claim carries the kernel's float
// arithmetic: without it E at r = 1, mu = 0.129 was 1.8e-7 below the reference, twice its claim.
TEST(Ltc, MagnitudeWithinItsClaim) {
  const int n = 16;
  const LtcFit f = fitLtc(runner(), LtcLobeSpec{NDF_GGX, GAF_SMITH_CORRELATED}, n);
  std::vector<size_t> at;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      if (x <= 1 || x == n - 1 || y == 0 || y == n - 1) at.push_back(static_cast<size_t>(y) * n + x);
  std::vector<reference::Moments> ref(at.size());
  brdfbake::ladder::onTwoThreads(at.size(), [&](size_t k) {
    const int x = static_cast<int>(at[k] % n), y = static_cast<int>(at[k] / n);
    const double r = static_cast<float>(std::max(ltcRoughness(x, n), std::sqrt(kLtcMinAlpha)));
    ref[k] = reference::albedo(NDF_GGX, GAF_SMITH_CORRELATED, r, static_cast<float>(ltcMu(y, n)));
  });
  for (size_t k = 0; k < at.size(); ++k) {
    const size_t t = at[k];
    EXPECT_NEAR(f.e[t], ref[k].a + ref[k].b, f.eBound[t]) << "x " << t % n << " y " << t / n;
    EXPECT_NEAR(f.b[t], ref[k].b, f.eBound[t]) << "x " << t % n << " y " << t / n;
  }
}

// The reference distance (tables/ltc/ltc_reference.h: 1 - int min(p, D) in the LTC's own cosine
// coordinates, nested adaptive Gauss-Kronrod) against a second, independent rule: the sphere
// quadrature of |p - D| above, where that one converges (r >= 0.5; at the grazing cap it integrates
// p itself only to 5.7e-6, so the views stop short of it). The sphere rule integrates p, the
// reference takes int p = 1: E's claim lies between them, and the sphere rule's kinks (where p = D)
// leave it 1.1e-6 from its own doubling.
TEST(Ltc, DistanceReferenceAgreesWithTheSphereQuadrature) {
  const int n = 16;
  const LtcLobeSpec lobe{NDF_GGX, GAF_SMITH_CORRELATED};
  const LtcFit f = fitLtc(runner(), lobe, n);
  for (int x : {8, 15})
    for (int y : {0, 5, 14}) {
      const size_t t = static_cast<size_t>(y) * n + x;
      const float s[4] = {f.store[0][t], f.store[1][t], f.store[2][t], f.store[3][t]};
      const LtcDistance ref = ltcDistanceReference(lobe, x, y, n, s, f.e[t]);
      const brdf64::LtcLobe L = ltcTexelLobe(lobe, x, y, n, f.e[t]);
      const brdf64::Ltc l = brdf64::ltc_from_stored(s[0], s[1], s[2], s[3]);
      const double sphere = 0.5 * sphereIntegral(
                                      [&](double a, double b, double c) {
                                        return std::fabs(brdf64::ltc_lobe_p(&L, a, b, c) - brdf64::ltc_D(l, a, b, c));
                                      },
                                      128, 4096);
      EXPECT_LE(ref.err, 1e-6) << "x " << x << " y " << y;
      EXPECT_NEAR(sphere, ref.tv, ref.err + 0.5 * f.eBound[t] / f.e[t] + 2e-6) << "x " << x << " y " << y;
    }
}

// Each texel's distance and its claim against the reference at the texels given, on two threads; returns how many were
// measured in double on the host, and appends the line it prints (the largest error / claim) to `said`.
int expectDistancesHold(const LtcLobeSpec& lobe, const LtcFit& f, const std::vector<size_t>& texels,
                        std::string& said) {
  const int n = f.n;
  std::vector<LtcDistance> ref(texels.size());
  brdfbake::ladder::onTwoThreads(texels.size(), [&](size_t k) {
    const size_t t = texels[k];
    if (f.e[t] >= kLtcNegligibleE) ref[k] = ltcDistanceReference(lobe, n, f.store, f.e, t);
  });
  int inDouble = 0;
  double worst = 0;
  for (size_t k = 0; k < texels.size(); ++k) {
    const size_t t = texels[k];
    const int x = static_cast<int>(t % n), y = static_cast<int>(t / n);
    if (f.e[t] < kLtcNegligibleE) {
      EXPECT_EQ(f.tv[t], 1.0f) << lobe.name() << " x " << x << " y " << y << ": a lobe without light states 1";
      continue;
    }
    inDouble += ltcMeasuredInDouble(lobe, x, y, n);
    const double d = std::fabs(f.tv[t] - ref[k].tv), claim = f.tvErr[t] + ref[k].err;
    worst = std::max(worst, d / claim);
    EXPECT_LE(d, claim) << lobe.name() << " " << n << "^2 x " << x << " y " << y << ": estimate " << f.tv[t]
                        << ", reference " << ref[k].tv << " (+- " << ref[k].err << ")";
  }
  testing_docs::say(said, "%s %d^2: %zu texels, the largest error %.2f of its claim, %d measured in double\n",
                    lobe.name().c_str(), n, texels.size(), worst, inDouble);
  return inDouble;
}

std::vector<size_t> everyTexel(int n) {
  std::vector<size_t> t(static_cast<size_t>(n) * n);
  for (size_t k = 0; k < t.size(); ++k) t[k] = k;
  return t;
}

// The distance each texel states, and its claim, against the reference where they are hardest:
// every texel of a 16^2 GGX fit and of 8^2 sheen and diffuse fits. r = 0 (alpha = 1e-5) is measured
// in double: in float the estimate misses there (tools/bite.sh ltc-distance-in-float fails this test).
TEST(Ltc, DistanceEstimateHoldsAgainstTheReference) {
  const LtcLobeSpec ggx{NDF_GGX, GAF_SMITH_CORRELATED};
  std::string said;  // docs/ltc.md quotes the largest
  EXPECT_GE(expectDistancesHold(ggx, fitLtc(runner(), ggx, 16), everyTexel(16), said), 16);
  for (const LtcLobeSpec& lobe : {LtcLobeSpec{NDF_CHARLIE, GAF_CHARLIE_SMITH}, LtcLobeSpec{-1, -1, DIFFUSE_OREN_NAYAR}})
    expectDistancesHold(lobe, fitLtc(runner(), lobe, 8), everyTexel(8), said);
  testing_docs::expectPagesQuote(said);
}

// The default 64^2 fit (about 6 minutes on two cores, behind the label `sweep`): its first four and
// last roughness rows, first and last views, and every second row. Where the shifts' spread alone
// missed (r = 10/63, mu = 0.91: 14 standard errors), the claim's tenth of the distance holds.
TEST(Ltc, DISABLED_DistanceEstimateHoldsAtEverySecondRow) {
  const int n = 64;
  std::vector<size_t> texels;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      if (x % 2 == 0 || x <= 3 || x == n - 1 || y == 0 || y == n - 1) texels.push_back(static_cast<size_t>(y) * n + x);
  std::string said;
  EXPECT_GE(expectDistancesHold(LtcLobeSpec{NDF_GGX, GAF_SMITH_CORRELATED}, defaultLtcFit(), texels, said), 3 * n);
  testing_docs::expectPagesQuote(said);
}

}  // namespace
