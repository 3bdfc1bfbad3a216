// Fresnel models: closed forms (normal incidence, the critical angle, k = 0), the kernels' real
// forms against the reference's complex amplitudes, and the Fresnel-weighted albedo on the device
// against the independent reference, stiff cases included (eta near 1, eta < 1 across the critical
// angle, conductors with k up to 10).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <future>
#include <random>

#include "cl/device.h"
#include "cl/runner.h"
#include "tables/error_model.h"
#include "common/brdf_host.h"
#include "common/material.h"
#include "common/models.h"
#include "reference/reference.h"
#include "reference_cache.h"
#include "test_device.h"

namespace {
using namespace brdfbake;

using testing_device::rel;
using testing_device::runner;

struct Case {
  const char* name;
  int model;
  double x, y;
};
const Case kCases[] = {
    {"schlick F0=0.04", FRESNEL_SCHLICK, 0.04, 0},
    {"dielectric eta=1.5", FRESNEL_DIELECTRIC, 1.5, 0},
    {"dielectric eta=1.0001", FRESNEL_DIELECTRIC, 1.0001, 0},
    {"dielectric eta=1.01", FRESNEL_DIELECTRIC, 1.01, 0},
    {"dielectric eta=0.67", FRESNEL_DIELECTRIC, 1 / 1.5, 0},
    {"dielectric eta=0.95", FRESNEL_DIELECTRIC, 0.95, 0},
    {"schlick-tir eta=0.67", FRESNEL_SCHLICK_TIR, 1 / 1.5, 0},
    {"conductor gold", FRESNEL_CONDUCTOR, 0.18, 3.4},
    {"conductor k=10", FRESNEL_CONDUCTOR, 1.5, 10},
    {"f82-tint", FRESNEL_F82_TINT, 0.9, 0.6},
};

HemiWeight weightOf(const Case& c) {
  return fresnelWeight(c.model, c.x, c.model == FRESNEL_F82_TINT ? brdf64::fresnel_f82_b(c.x, c.y) : c.y);
}

TEST(Fresnel, ClosedForms) {
  for (double eta : {1.0001, 1.01, 1.33, 1.5, 2.4}) {
    double f0 = std::pow((eta - 1) / (eta + 1), 2);
    EXPECT_NEAR(brdf64::fresnel_dielectric(eta, 1.0), f0, 1e-15) << eta;
    EXPECT_NEAR(reference::fresnel({FRESNEL_DIELECTRIC, eta, 0}, 1.0), f0, 1e-15) << eta;
    // k = 0 conductor = dielectric, everywhere
    for (double c : {0.01, 0.3, 0.7, 1.0})
      EXPECT_NEAR(brdf64::fresnel_conductor(eta, 0.0, c), brdf64::fresnel_dielectric(eta, c), 1e-14) << eta << " " << c;
  }
  // conductor at normal incidence: ((eta-1)^2 + k^2)/((eta+1)^2 + k^2)
  for (auto [eta, k] : {std::pair{0.18, 3.4}, {1.5, 10.0}, {0.05, 0.5}})
    EXPECT_NEAR(brdf64::fresnel_conductor(eta, k, 1.0),
                ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k), 1e-14);
  // eta < 1: F = 1 from the critical angle on, continuous there
  double eta = 1 / 1.5, crit = std::sqrt(1 - eta * eta);
  EXPECT_EQ(brdf64::fresnel_dielectric(eta, crit * (1 - 1e-9)), 1.0);
  EXPECT_NEAR(brdf64::fresnel_dielectric(eta, crit * (1 + 1e-12)), 1.0, 1e-5);
  EXPECT_LT(brdf64::fresnel_dielectric(eta, crit * 1.01), 0.9);
  // F82-tint: Schlick at mu = 0 and 1, the tint times Schlick at mu = 1/7
  double b = brdf64::fresnel_f82_b(0.9, 0.6);
  EXPECT_NEAR(brdf64::fresnel_f82_tint(0.9, b, 1.0), 0.9, 1e-15);
  EXPECT_NEAR(brdf64::fresnel_f82_tint(0.9, b, 0.0), 1.0, 1e-15);
  EXPECT_NEAR(brdf64::fresnel_f82_tint(0.9, b, 1.0 / 7), 0.6 * brdf64::fresnel_schlick(0.9, 1.0 / 7), 1e-14);
  // Schlick's F_avg = (20 F0 + 1)/21
  for (double f0 : {0.0, 0.04, 0.5, 1.0})
    EXPECT_NEAR(reference::fresnelAvg({FRESNEL_SCHLICK, f0, 0}), (20 * f0 + 1) / 21, 1e-13) << f0;
}

// F_avg as the baker computes it (closed forms, or adaptive on the kernels' formulas) against the
// reference's adaptive average of the complex amplitudes.
TEST(Fresnel, AverageFresnelClosedFormsAndQuadrature) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int t = 0; t < 25; ++t) {
    double f0 = u(rng), tint = u(rng), eta = 0.1 + 3 * u(rng), k = 10 * u(rng);
    const Case cs[] = {{"schlick", FRESNEL_SCHLICK, f0, 0},
                       {"f82-tint", FRESNEL_F82_TINT, f0, tint},
                       {"dielectric", FRESNEL_DIELECTRIC, eta, 0},
                       {"schlick-tir", FRESNEL_SCHLICK_TIR, eta, 0},
                       {"conductor", FRESNEL_CONDUCTOR, eta, k}};
    for (const Case& c : cs) {
      FresnelChoice f;
      f.model = c.model;
      if (c.model == FRESNEL_SCHLICK || c.model == FRESNEL_F82_TINT) f.f0 = {c.x};
      if (c.model == FRESNEL_F82_TINT) f.f82 = {c.y};
      if (c.model != FRESNEL_SCHLICK && c.model != FRESNEL_F82_TINT) f.eta = {c.x};
      if (c.model == FRESNEL_CONDUCTOR) f.k = {c.y};
      double want = reference::fresnelAvg({c.model, c.x, c.y});
      ASSERT_NEAR(fresnelAverage(f, 0), want, 1e-10) << c.name << " x " << c.x << " y " << c.y;
    }
  }
  // just below eta = 1, where F's square-root end sits next to mu = 0 (the critical cosine 0.0014
  // at eta = 1 - 1e-6)
  for (int model : {FRESNEL_DIELECTRIC, FRESNEL_SCHLICK_TIR})
    for (double eta : {0.999, 0.9999, 0.999999}) {
      FresnelChoice f;
      f.model = model;
      f.eta = {eta};
      ASSERT_NEAR(fresnelAverage(f, 0), reference::fresnelAvg({model, eta, 0}), 1e-10) << model << " eta " << eta;
    }
  // the limits: eta -> 1 reflects nothing, eta -> 0 (total internal reflection everywhere) all
  EXPECT_NEAR(fresnelAverage(FRESNEL_DIELECTRIC, 1.0, 0), 0.0, 1e-15);
  EXPECT_NEAR(fresnelAverage(FRESNEL_DIELECTRIC, 1e-4, 0), 1.0, 1e-6);
}

// The kernels' real forms against the complex amplitudes, at random angles.
TEST(Fresnel, KernelFormsMatchComplexAmplitudes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int t = 0; t < 2000; ++t) {
    double c = u(rng), eta = 0.05 + 3 * u(rng), k = 10 * u(rng) * u(rng);
    ASSERT_NEAR(brdf64::fresnel_conductor(eta, k, c), reference::fresnel({FRESNEL_CONDUCTOR, eta, k}, c), 1e-12)
        << "eta " << eta << " k " << k << " c " << c;
    ASSERT_NEAR(brdf64::fresnel_dielectric(eta, c), reference::fresnel({FRESNEL_DIELECTRIC, eta, 0}, c), 1e-12)
        << "eta " << eta << " c " << c;
  }
}

// The Fresnel-weighted albedo (B of the HEMI_FRESNEL moments) against the reference, ggx +
// smith-correlated: a 5x5 node grid (the table's edges, the corner) and a 4x4 texel-centre grid
// on the device, a spread of their texels checked (the reference takes seconds per value at
// grazing views; two threads). At the corner (mu = 0, r = 0) o.h -> 0, so F -> F(0) = 1 for every
// model and the value is the F = 1 corner limit: checked against the reference's F = 1 value.
TEST(Fresnel, AlbedoMatchesReference) {
  const int ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED;
  struct Texel {
    bool node;
    int i, j;
  };
  const Texel texels[] = {{true, 0, 0}, {true, 0, 2}, {true, 0, 4}, {true, 1, 1},  {true, 1, 4},  {true, 2, 0},
                          {true, 2, 2}, {true, 3, 3}, {true, 4, 4}, {false, 0, 3}, {false, 2, 1}, {false, 3, 2}};
  for (const Case& c : kCases) {
    KernelTable tn = runner().hemisphere(ndf, gaf, 5, 5, true, weightOf(c));
    KernelTable tc = runner().hemisphere(ndf, gaf, 4, 4, false, weightOf(c));
    reference::Weight w{reference::Weight::Fresnel, {c.model, c.x, c.y}};
    std::vector<std::future<reference::Moments>> refs;
    for (const Texel& t : texels) {
      int n = t.node ? 5 : 4;
      double mu = static_cast<float>(t.node ? t.i / (n - 1.0) : (t.i + 0.5) / n);
      double r = static_cast<float>(t.node ? t.j / (n - 1.0) : (t.j + 0.5) / n);
      refs.push_back(std::async(std::launch::async, [=] {
        const reference::Weight wt = mu == 0 && r == 0 ? reference::Weight{} : w;
        std::vector<double> v =
            testing_ref::cached(testing_ref::keyOf("albedo " + ndfNames()[ndf] + " " + gafNames()[gaf],
                                                   {r, mu, double(wt.kind), double(wt.f.model), wt.f.x, wt.f.y}),
                                [&] {
                                  reference::Moments m = reference::albedo(ndf, gaf, r, mu, wt);
                                  return std::vector<double>{m.a, m.b};
                                });
        reference::Moments m;
        m.a = v[0], m.b = v[1];
        return m;
      }));
    }
    double worst = 0, worstBound = 0;
    for (size_t q = 0; q < std::size(texels); ++q) {
      const Texel& t = texels[q];
      const KernelTable& kt = t.node ? tn : tc;
      int n = kt.width;
      double mu = static_cast<float>(t.node ? t.i / (n - 1.0) : (t.i + 0.5) / n);
      double r = static_cast<float>(t.node ? t.j / (n - 1.0) : (t.j + 0.5) / n);
      reference::Moments ref = refs[q].get();
      double want = mu == 0 && r == 0 ? ref.e() : ref.b;
      size_t k = static_cast<size_t>(t.j) * n + t.i;
      double e = std::max(rel(kt.planes[1][k], want), rel(kt.planes[2][k], ref.e()));
      worst = std::max(worst, e);
      worstBound = std::max(worstBound, static_cast<double>(kt.err[k]));
      EXPECT_TRUE(std::isfinite(kt.planes[1][k]));
      // the claim as the bake makes it: the estimate + the float model of the texel's largest moment
      // (+ the reference's own accuracy at mu = 0, approached from inside)
      double scale = 0;
      for (int p = 0; p < 3; ++p) scale = std::max(scale, std::fabs(static_cast<double>(kt.planes[p][k])));
      EXPECT_LE(e, kt.err[k] + floatArithmeticError(scale) + (mu == 0 ? 1e-7 : 0))
          << c.name << " mu=" << mu << " r=" << r << " device " << kt.planes[1][k] << " ref " << want;
      EXPECT_LE(e, 1e-5) << c.name << " mu=" << mu << " r=" << r;
      EXPECT_LE(kt.err[k], 1e-5) << c.name << " mu=" << mu << " r=" << r << ": the claimed bound";
    }
    std::printf("%-24s worst error %.2e, worst bound %.2e\n", c.name, worst, worstBound);
  }
}

// Total internal reflection (eta = 1/1.5), in double on the host: every texel's claim (the chosen
// budget's estimate with its floor, hemi_rel_error) against the same rule at level 3, on a 16x16
// grid of ggx + smith-correlated, and the two texels where the estimate falls 3.2 times below the
// error without the graded panels (mu 0.92, r 0.86: whole circles just above the critical angle)
// and stands 240 times above it with a horizon break just short of the kink (mu 0.73, r 0.48).
// Every claim is under 4e-7.
TEST(Fresnel, TirEstimatesBoundTheConvergedRule) {
  const int ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED;
  const double eta = static_cast<float>(1 / 1.5);
  std::vector<std::pair<double, double>> pts = {{0.921875, 0.859375}, {0.734375, 0.484375}};
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) pts.push_back({(i + 0.5) / 16, (j + 0.5) / 16});
  double worstClaim = 0, worstRatio = 0;
  for (auto [mu, r] : pts) {
    auto h = brdf64::hemisphere_texel_weighted(ndf, gaf, mu, r, 3e-7, HEMI_FRESNEL, FRESNEL_DIELECTRIC, eta, 0);
    brdf64::BrdfParams p = brdf64::hemisphere_texel_params(ndf, gaf, mu, r);
    p.moments = HEMI_FRESNEL;
    p.fresnel = FRESNEL_DIELECTRIC;
    p.fr_x = eta;
    p.fr_y = 0;
    auto ref = brdf64::hemi_rule(ndf, gaf, p, mu, 3);
    double claim = brdf64::hemi_rel_error(h);
    double err = std::max({std::fabs(h.a - ref.a), std::fabs(h.b - ref.b), std::fabs(h.a + h.b - ref.a - ref.b)});
    worstClaim = std::max(worstClaim, claim);
    worstRatio = std::max(worstRatio, err / claim);
    EXPECT_LE(err, claim) << "mu " << mu << " r " << r;
    EXPECT_LE(claim, 4e-7) << "mu " << mu << " r " << r;
  }
  std::printf("TIR eta = 1/1.5: largest claim %.3g, largest error/claim %.2f\n", worstClaim, worstRatio);
}

// The F82-tint split: F0 A + B - b C from the split-sum pair and the C moment equals the F82-tint
// albedo integrated directly, at every texel of a 16x16 table (both are device results, each
// within its bound of the exact value).
TEST(Fresnel, F82SplitSumMatchesDirectAlbedo) {
  const int ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED, n = 16;
  KernelTable ab = runner().hemisphere(ndf, gaf, n, n, false);
  KernelTable c = runner().hemisphere(ndf, gaf, n, n, false, HemiWeight{HEMI_F82C, 0, 0, 0});
  for (auto [f0, tint] : {std::pair{0.9, 0.6}, {0.04, 1.0}, {0.5, 0.2}}) {
    double b = brdf64::fresnel_f82_b(f0, tint);
    Case cs{"f82", FRESNEL_F82_TINT, f0, tint};
    KernelTable direct = runner().hemisphere(ndf, gaf, n, n, false, weightOf(cs));
    double worst = 0;
    for (size_t k = 0; k < direct.planes[1].size(); ++k) {
      double split = f0 * ab.planes[0][k] + ab.planes[1][k] - b * c.planes[1][k];
      double tol = (f0 + 1 + std::fabs(b) + 1) * floatArithmeticError(1.0) + ab.err[k] + c.err[k] + direct.err[k];
      worst = std::max(worst, std::fabs(split - direct.planes[1][k]));
      ASSERT_NEAR(split, direct.planes[1][k], tol) << "f0 " << f0 << " tint " << tint << " texel " << k;
    }
    std::printf("f82 f0=%g tint=%g: |F0 A + B - b C - E_F82| <= %.2e\n", f0, tint, worst);
  }
}

// The average of a Fresnel albedo (albedo-avg with --fresnel) against the reference's own average
// (adaptive in mu over its adaptive albedo), at the 4 texel centres of r. Smooth Fresnels here;
// those with a critical cosine at FresnelEdge.AverageAlbedoAtTheStiffCorner
// (tests/tables/microfacet/fresnel_edge_test.cpp).
TEST(Fresnel, AverageAlbedoMatchesReference) {
  const int ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED, n = 4;
  for (const Case& c : {kCases[1], kCases[7], kCases[8]}) {
    KernelTable t = runner().albedoAvg(ndf, gaf, n, false, weightOf(c));
    reference::Weight w{reference::Weight::Fresnel, {c.model, c.x, c.y}};
    for (int j = 0; j < n; ++j) {
      double r = static_cast<float>((j + 0.5) / n);
      double want =
          testing_ref::cached1(testing_ref::keyOf("albedoAvg " + ndfNames()[ndf] + " " + gafNames()[gaf] + " fresnel",
                                                  {r, double(c.model), c.x, c.y}),
                               [&] { return reference::albedoAvg(ndf, gaf, r, w); });
      double e = rel(t.planes[0][j], want);
      EXPECT_LE(e, t.err[j] + avgFloatArithmeticError(t.planes[0][j], ndf, gaf, true))
          << c.name << " r=" << r << " device " << t.planes[0][j] << " ref " << want;
      EXPECT_LE(e, 1e-5) << c.name << " r=" << r;
    }
  }
}

}  // namespace
