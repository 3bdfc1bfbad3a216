// The float forms the kernels use in place of library functions (kernels/brdf/ndf.h
// beckmann_cLambda, kernels/integrate/azimuth.h cos_arc) and the values the estimators set once
// per texel (integrate/integrand.h hemi_view): each against the double form it stands for.
// brdf32 is the device's float arithmetic on one lane, brdf64 the libm forms in double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/brdf_host.h"

namespace {
constexpr double kPi = 3.14159265358979323846;

// The Beckmann c Lambda in float against libm's erfc in double, as G uses it: relative to
// c + c Lambda (G1 = c/(c + c Lambda)), over a from 0 to 6 and alpha sin theta from 1e-3 to 1.
// Measured largest: 1.8e-7 (3 ulp, at a = 0.019); the bound leaves 1.7x.
TEST(FloatForms, BeckmannLambdaWithinFiveUlpOfLibm) {
  double worst = 0, worstA = 0;
  for (double as : {1e-3, 0.03, 0.2, 0.5, 1.0}) {
    for (int k = 0; k <= 6000; ++k) {
      const double a = k * 1e-3;
      const float c = static_cast<float>(a * as);
      // s2 such that alpha sqrt(s2) = as at alpha = 1 (r = 1)
      const float s2 = static_cast<float>(as * as);
      brdf32::BrdfParams p32 = brdf32::brdf_params(NDF_BECKMANN, GAF_SMITH, 1.0f);
      brdf64::BrdfParams p64 = brdf64::brdf_params(NDF_BECKMANN, GAF_SMITH, 1.0);
      const double got = brdf32::ndf_cLambda(NDF_BECKMANN, p32, c, s2);
      const double want = brdf64::ndf_cLambda(NDF_BECKMANN, p64, static_cast<double>(c), static_cast<double>(s2));
      ASSERT_TRUE(std::isfinite(got)) << "a " << a << " as " << as;
      const double e = std::fabs(got - want) / (static_cast<double>(c) + want);
      if (e > worst) worst = e, worstA = a;
    }
  }
  EXPECT_LE(worst, 3e-7) << "at a = " << worstA;
  std::printf("beckmann c Lambda, float form: largest error %.2e of c + c Lambda (a = %.3f)\n", worst, worstA);
}

// The form's own rounding, relative to c Lambda itself over a in [0, 1] (alpha sin = 0.5, where
// exp(-a^2)'s rounding stays below 6e-8): the root mean square measured here 6.9e-8 with t^2
// compensated for the rounding of 1 + a, 9.9e-8 without (`tools/bite.sh beckmann-compensation`).
TEST(FloatForms, BeckmannLambdaRoundingIsCompensated) {
  brdf32::BrdfParams p32 = brdf32::brdf_params(NDF_BECKMANN, GAF_SMITH, 1.0f);
  brdf64::BrdfParams p64 = brdf64::brdf_params(NDF_BECKMANN, GAF_SMITH, 1.0);
  double sum = 0;
  int n = 0;
  for (int k = 1; k <= 10000; ++k) {
    const float c = static_cast<float>(k * 1e-4 * 0.5), s2 = 0.25f;
    const double got = brdf32::ndf_cLambda(NDF_BECKMANN, p32, c, s2);
    const double want = brdf64::ndf_cLambda(NDF_BECKMANN, p64, static_cast<double>(c), 0.25);
    sum += (got / want - 1) * (got / want - 1);
    ++n;
  }
  const double rms = std::sqrt(sum / n);
  std::printf("beckmann c Lambda, float form: rms relative error %.2e over a in [0, 1]\n", rms);
  EXPECT_LE(rms, 8.2e-8);
}

// Below the surface (c < 0) the float form follows erfc(-x) = 2 - erfc(x); at the normal
// (sin = 0) and far above the Lambda's scale it is 0, finite everywhere.
TEST(FloatForms, BeckmannLambdaEdges) {
  brdf32::BrdfParams p32 = brdf32::brdf_params(NDF_BECKMANN, GAF_SMITH, 0.7f);
  brdf64::BrdfParams p64 = brdf64::brdf_params(NDF_BECKMANN, GAF_SMITH, 0.7);
  for (float c : {-0.9f, -0.5f, -0.1f, -1e-3f}) {
    const float s2 = (1 - c) * (1 + c);
    const double got = brdf32::ndf_cLambda(NDF_BECKMANN, p32, c, s2);
    const double want = brdf64::ndf_cLambda(NDF_BECKMANN, p64, static_cast<double>(c), static_cast<double>(s2));
    EXPECT_NEAR(got, want, 4e-7 * std::max(1.0, std::fabs(want))) << "c " << c;
  }
  EXPECT_EQ(brdf32::ndf_cLambda(NDF_BECKMANN, p32, 1.0f, 0.0f), 0.0f);
  const float far = brdf32::ndf_cLambda(NDF_BECKMANN, p32, 0.999f, 1e-6f);  // a ~ 2000
  EXPECT_TRUE(std::isfinite(far));
  EXPECT_LE(far, 1e-30f);
}

// cos_arc on the azimuth's range [0, pi], float against libm's cos of the same float argument:
// within 2e-7 (measured 1.6e-7 here, where the host compiles Horner without fused multiply-adds;
// 1.4e-7 with them, as the device runs it: tools/fit_polynomials.py cos); the double form is libm's.
TEST(FloatForms, CosArcWithinItsBoundOnTheAzimuthRange) {
  double worst = 0;
  for (int k = 0; k <= 200000; ++k) {
    const float x = static_cast<float>(kPi * k / 200000.0);
    worst = std::max(worst, std::fabs(static_cast<double>(brdf32::cos_arc(x)) - std::cos(static_cast<double>(x))));
  }
  std::printf("cos_arc, float form: largest error %.2e of cos on [0, pi]\n", worst);
  EXPECT_LE(worst, 2e-7);
  EXPECT_EQ(brdf64::cos_arc(1.2345), std::cos(1.2345));
}

// The view's Lambda set once per texel (hemi_view) gives G exactly as computing it at the node
// does, for every GAF and NDF, the tabulated exact Lambdas' alpha column included (double, where
// the column's sums are exact to rounding; float within a few ulp).
TEST(FloatForms, ViewSetOncePerTexelGivesTheSameG) {
  for (int ndf : {NDF_GGX, NDF_BECKMANN, NDF_BLINN_PHONG, NDF_GAUSSIAN, NDF_CHARLIE}) {
    for (int gaf = 0; gaf < GAF_COUNT; ++gaf) {
      for (double r : {0.05, 0.4, 0.9}) {
        const double mu = 0.37, s = std::sqrt(1 - mu * mu);
        brdf64::BrdfParams p = brdf64::brdf_params(ndf, gaf, r);
        float col[SMITH_NZ];
        brdf32::BrdfParams p32 = brdf32::brdf_params(ndf, gaf, static_cast<float>(r));
        brdf32::BrdfParams v32 = brdf32::hemi_view(ndf, gaf, p32, static_cast<float>(mu), static_cast<float>(s), col);
        for (double ni : {0.02, 0.3, 0.8}) {
          const double nh = 0.9, oh = 0.6, s2i = (1 - ni) * (1 + ni);
          const double g0 = brdf64::gaf_G_over_no(gaf, ndf, p, ni, mu, nh, oh, s2i, s * s);
          float fcol[SMITH_NZ];
          brdf64::BrdfParams v = brdf64::hemi_view(ndf, gaf, p, mu, s, fcol);
          const double g1 = brdf64::gaf_G_over_no(gaf, ndf, v, ni, mu, nh, oh, s2i, s * s);
          // the column holds floats: the tabulated pairs agree to float rounding of V
          EXPECT_NEAR(g1, g0, 1e-6 * std::fabs(g0)) << ndf << "/" << gaf << " r " << r << " ni " << ni;
          const float f0 = brdf32::gaf_G_over_no(gaf, ndf, p32, static_cast<float>(ni), static_cast<float>(mu),
                                                 static_cast<float>(nh), static_cast<float>(oh),
                                                 static_cast<float>(s2i), static_cast<float>(s * s));
          const float f1 = brdf32::gaf_G_over_no(gaf, ndf, v32, static_cast<float>(ni), static_cast<float>(mu),
                                                 static_cast<float>(nh), static_cast<float>(oh),
                                                 static_cast<float>(s2i), static_cast<float>(s * s));
          EXPECT_NEAR(f1, f0, 5e-7 * std::fabs(f0)) << ndf << "/" << gaf << " r " << r << " ni " << ni;
        }
      }
    }
  }
}
}  // namespace
