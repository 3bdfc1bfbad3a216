// The exact Smith Lambda of Blinn-Phong and the gaussian (GAF smith-exact, smith-correlated-exact;
// docs/MODELS.md "Exact Smith Lambda"): the kernel's tabulated form against the reference's
// quadrature, the weak white furnace for every NDF, and the Smith albedo on the device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "cl/device.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/models.h"
#include "reference/reference.h"

namespace {
namespace ref = brdfbake::reference;
const std::string& ndfName(int ndf) { return brdfbake::ndfNames()[ndf]; }

// The reference's quadrature reproduces the closed forms where they are exact (ggx, beckmann).
TEST(SmithExact, ReferenceQuadratureMatchesClosedForms) {
  for (int ndf : {NDF_GGX, NDF_BECKMANN})
    for (double r : {0.01, 0.1, 0.5, 1.0})
      for (double mu : {1e-4, 0.05, 0.3, 0.7, 0.95}) {
        double s2 = (1 - mu) * (1 + mu);
        brdf64::BrdfParams p = brdf64::brdf_params(ndf, GAF_SMITH, r);
        double closed = brdf64::ndf_cLambda(ndf, p, mu, s2) / mu;
        double quad = ref::smithLambdaExact(ndf, r, mu);
        if (closed < 1e-200) continue;  // underflow (beckmann at small r, steep mu)
        EXPECT_NEAR(quad / closed, 1.0, 1e-10) << ndfName(ndf) << " r " << r << " mu " << mu;
      }
}

// Kernel's Lambda vs the reference's, over r in (0, 1] and mu in (0, 1). Criterion: the error in
// Lambda relative to 1 + Lambda (the relative error of G1 = 1/(1 + Lambda)) within 1e-6 in double
// and float rounding in float; relative to Lambda itself where Lambda > 1e-3 (to ~1e-5: see below).
TEST(SmithExact, KernelLambdaMatchesReference) {
  for (int ndf : {NDF_BLINN_PHONG, NDF_GAUSSIAN}) {
    double worstG = 0, worstL = 0, worstG32 = 0;
    for (double r : {0.01, 0.05, 0.1, 0.2, 0.33, 0.5, 0.61, 0.75, 0.87, 0.95, 1.0})
      for (double mu : {1e-4, 0.01, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.75, 0.9, 0.97, 0.999}) {
        double s2 = (1 - mu) * (1 + mu);
        double want = ref::smithLambdaExact(ndf, r, mu);
        brdf64::BrdfParams p = brdf64::brdf_params(ndf, GAF_SMITH_EXACT, r);
        double got = brdf64::ndf_cLambda_exact(ndf, p, mu, s2) / mu;
        brdf32::BrdfParams pf = brdf32::brdf_params(ndf, GAF_SMITH_EXACT, float(r));
        double got32 = brdf32::ndf_cLambda_exact(ndf, pf, float(mu), float(s2)) / float(mu);
        ASSERT_TRUE(std::isfinite(got) && std::isfinite(got32)) << ndfName(ndf) << " r " << r << " mu " << mu;
        worstG = std::max(worstG, std::fabs(got - want) / (1 + want));
        worstG32 = std::max(worstG32, std::fabs(got32 - want) / (1 + want));
        if (want > 1e-3) worstL = std::max(worstL, std::fabs(got - want) / want);
      }
    std::printf("%s: max |dLambda|/(1+Lambda) %.2e (float %.2e), max |dLambda|/Lambda (Lambda > 1e-3) %.2e\n",
                ndfName(ndf).c_str(), worstG, worstG32, worstL);
    EXPECT_LE(worstG, 1e-6) << ndfName(ndf);
    // near the normal at r ~ 1 Lambda falls as a non-integer power of (1 - z), which the cubic
    // interpolation follows only to ~1e-5 of Lambda (tools/smith_tables.cpp measures 3.4e-5 on
    // cell centres there); G1 stays within 1e-6 (above)
    EXPECT_LE(worstL, 4e-5) << ndfName(ndf);
    EXPECT_LE(worstG32, 2e-6) << ndfName(ndf);
  }
}

// Finite at the ends: grazing (mu -> 0), mirror (r -> 0), and their corner.
TEST(SmithExact, FiniteAtTheEdges) {
  for (int ndf = 0; ndf < NDF_COUNT; ++ndf)
    if (brdfbake::pairSupported(ndf, GAF_SMITH_EXACT))
      for (double r : {0.0, 1e-4, 0.01, 1.0})
        for (double mu : {0.0, 1e-7, 1.0}) {
          // ggx's closed form is 0/0 at the corner itself, which no integrator evaluates
          // (hemisphere_texel_params moves it inside, HEMI_CORNER_R)
          if (ndf == NDF_GGX && r == 0 && mu == 0) continue;
          double s2 = (1 - mu) * (1 + mu);
          brdf64::BrdfParams p = brdf64::brdf_params(ndf, GAF_SMITH_EXACT, r);
          brdf32::BrdfParams pf = brdf32::brdf_params(ndf, GAF_SMITH_EXACT, float(r));
          double v = brdf64::ndf_cLambda_exact(ndf, p, mu, s2);
          float vf = brdf32::ndf_cLambda_exact(ndf, pf, float(mu), float(s2));
          EXPECT_TRUE(std::isfinite(v) && v >= 0) << ndfName(ndf) << " r " << r << " mu " << mu << ": " << v;
          EXPECT_TRUE(std::isfinite(vf) && vf >= 0) << ndfName(ndf) << " r " << r << " mu " << mu << ": " << vf;
        }
}

// GGX and Beckmann: the exact GAFs are smith / smith-correlated.
TEST(SmithExact, IdenticalForGgxAndBeckmann) {
  for (int ndf : {NDF_GGX, NDF_BECKMANN})
    for (double r : {0.1, 0.5, 1.0})
      for (double mu : {0.05, 0.5, 0.95}) {
        double s2 = (1 - mu) * (1 + mu);
        brdf64::BrdfParams p = brdf64::brdf_params(ndf, GAF_SMITH_EXACT, r);
        EXPECT_EQ(brdf64::ndf_cLambda_exact(ndf, p, mu, s2), brdf64::ndf_cLambda(ndf, p, mu, s2));
      }
}

// Weak white furnace with the exact Lambda: W(mu) = int G1(o) max(0, o.h) D dw_h = mu for every NDF,
// with the reference's G1 (its quadrature) and with the kernel's G1 (brdf64 and brdf32: the integral
// without G1 is W_ref (1 + Lambda_ref), so W_kernel = W_ref (1 + Lambda_ref)/(1 + Lambda_kernel)).
TEST(SmithExact, WeakWhiteFurnaceHoldsForEveryNdf) {
  for (int ndf = 0; ndf < NDF_COUNT; ++ndf) {
    if (!brdfbake::pairSupported(ndf, GAF_SMITH_EXACT)) continue;
    double worst = 0, worstK = 0, worstK32 = 0;
    for (double r : {0.1, 0.3, 0.5, 0.8, 1.0})
      for (double mu : {0.05, 0.2, 0.5, 0.8, 0.95}) {
        double w = ref::weakFurnace(ndf, GAF_SMITH_EXACT, r, mu);
        double lref = ref::smithLambdaExact(ndf, r, mu), s2 = (1 - mu) * (1 + mu);
        brdf64::BrdfParams p = brdf64::brdf_params(ndf, GAF_SMITH_EXACT, r);
        brdf32::BrdfParams pf = brdf32::brdf_params(ndf, GAF_SMITH_EXACT, float(r));
        double lk = brdf64::ndf_cLambda_exact(ndf, p, mu, s2) / mu;
        double lk32 = brdf32::ndf_cLambda_exact(ndf, pf, float(mu), float(s2)) / float(mu);
        worst = std::max(worst, std::fabs(w - mu) / mu);
        worstK = std::max(worstK, std::fabs(w * (1 + lref) / (1 + lk) - mu) / mu);
        worstK32 = std::max(worstK32, std::fabs(w * (1 + lref) / (1 + lk32) - mu) / mu);
      }
    std::printf("%s: weak furnace max relative deviation: reference G1 %.2e, kernel G1 %.2e (float %.2e)\n",
                ndfName(ndf).c_str(), worst, worstK, worstK32);
    EXPECT_LE(worst, 1e-6) << ndfName(ndf);
    EXPECT_LE(worstK, 1e-6) << ndfName(ndf);
    EXPECT_LE(worstK32, 2e-6) << ndfName(ndf);
  }
}

// The Smith albedo with the exact correlated GAF stays <= 1 (the single-scattering energy is at most
// what the weak furnace allows) on the device's 9 x 9 node grid, and matches the reference.
TEST(SmithExact, CorrelatedAlbedoAtMostOneOnDevice) {
  brdfbake::KernelRunner runner(brdfbake::selectDevice("").device);
  const int n = 9;  // node grid: mu = i/8, r = j/8
  for (int ndf : {NDF_BLINN_PHONG, NDF_GAUSSIAN}) {
    brdfbake::KernelTable t = runner.hemisphere(ndf, GAF_SMITH_CORRELATED_EXACT, n, n, true);
    double worst = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        size_t k = size_t(j) * n + i;
        double e = t.planes[2][k];
        worst = std::max(worst, e);
        EXPECT_LE(e, 1 + t.err[k] + 1e-6) << ndfName(ndf) << " mu " << i / 8.0 << " r " << j / 8.0;
      }
    std::printf("%s: max Smith albedo (smith-correlated-exact) on the 9x9 nodes %.7f\n", ndfName(ndf).c_str(), worst);
    // against the reference at a few nodes (each takes a while)
    for (auto [i, j] : {std::pair{2, 2}, {6, 4}, {1, 8}, {8, 6}, {4, 8}}) {
      double mu = i / 8.0, r = j / 8.0;
      double want = ref::albedo(ndf, GAF_SMITH_CORRELATED_EXACT, r, mu).e();
      EXPECT_NEAR(t.planes[2][size_t(j) * n + i], want, 1e-5) << ndfName(ndf) << " mu " << mu << " r " << r;
    }
  }
}

}  // namespace
