// The Fresnel albedo at its stiff corner: every Fresnel model at its extreme parameters (eta within
// 1e-6 to 1e-2 of 1 on both sides, eta 0.2 and 5, a conductor with k -> 0 and k = 10, F82-tint's
// tint 0 and 1), baked on the device, checked texel by texel where a narrow lobe meets F's steep
// edge: the first and last four mu columns and r rows of 32^2 and 64^2 tables (128^2 and every
// pair in the sweep below, ctest's FresnelSweep.EveryPairEverySize behind the label `sweep`).
//
// What a texel is checked against:
//   - the same rule in double at the refined budget with the eta asked for in double (brdf64,
//     fr_z = 0), whose own estimate is far below the float claim: the device's value must be within
//     its claim (its estimate + the float arithmetic, as the bake claims it) of it, and the claim at
//     most 4 times that error or the float floor, whichever is larger;
//   - the independent reference (host/reference, adaptive in the plain angles, the complex
//     amplitudes' Fresnel, cached in tests/data/reference_values.txt) at the corner texels where it
//     takes under a second; just below eta = 1 with mu next to the critical cosine it takes minutes
//     a texel (eta = 0.9999, mu = 1/64: > 5 min), and those texels are checked against the rule in
//     double only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <future>
#include <string>
#include <vector>

#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/models.h"
#include "reference/reference.h"
#include "reference_cache.h"
#include "tables/error_model.h"
#include "test_device.h"

namespace {
using namespace brdfbake;
using testing_device::rel;
using testing_device::runner;

struct Edge {
  std::string name;
  int model;
  double x, y;  // eta or F0; k or the F82 tint
};

std::vector<Edge> edges() {
  std::vector<Edge> v;
  for (double d : {1e-6, 1e-4, 1e-3, 1e-2}) {
    v.push_back({"dielectric eta=1-" + std::to_string(d), FRESNEL_DIELECTRIC, 1 - d, 0});
    v.push_back({"dielectric eta=1+" + std::to_string(d), FRESNEL_DIELECTRIC, 1 + d, 0});
  }
  v.push_back({"dielectric eta=0.2", FRESNEL_DIELECTRIC, 0.2, 0});
  v.push_back({"dielectric eta=5", FRESNEL_DIELECTRIC, 5, 0});
  v.push_back({"schlick-tir eta=0.9999", FRESNEL_SCHLICK_TIR, 0.9999, 0});
  v.push_back({"schlick-tir eta=1.0001", FRESNEL_SCHLICK_TIR, 1.0001, 0});
  v.push_back({"conductor eta=0.9999 k=1e-4", FRESNEL_CONDUCTOR, 0.9999, 1e-4});
  v.push_back({"conductor eta=1.5 k=10", FRESNEL_CONDUCTOR, 1.5, 10});
  v.push_back({"f82-tint F0=0.04 tint=0", FRESNEL_F82_TINT, 0.04, 0});
  v.push_back({"f82-tint F0=0.04 tint=1", FRESNEL_F82_TINT, 0.04, 1});
  return v;
}

HemiWeight weightOf(const Edge& e) {
  double y = e.model == FRESNEL_F82_TINT ? brdf64::fresnel_f82_b(e.x, e.y) : e.y;
  return fresnelWeight(e.model, e.x, y);
}

// The rule in double at the refined budget, at the eta asked for (no float rounding of it).
double doubleRule(int ndf, int gaf, const Edge& e, double mu, double r, double* est) {
  brdf64::BrdfParams p = brdf64::hemisphere_texel_params(ndf, gaf, mu, r);
  p.moments = HEMI_FRESNEL;
  p.fresnel = e.model;
  p.fr_x = e.x;
  p.fr_y = e.model == FRESNEL_F82_TINT ? brdf64::fresnel_f82_b(e.x, e.y) : e.y;
  p.fr_z = 0;
  brdf64::HemiResult h = brdf64::hemisphere_moments(ndf, gaf, p, mu, 1);
  brdf64::hemi_add_corner(mu, r, &h);
  *est = h.err_b / std::max(1.0, std::fabs(h.b));
  return h.b;
}

// The corner's texel indices of an n-wide axis: the first and the last four.
std::vector<int> cornerIndices(int n) {
  std::vector<int> v;
  for (int k = 0; k < 4; ++k) v.push_back(k);
  for (int k = n - 4; k < n; ++k) v.push_back(k);
  return v;
}

struct Worst {
  double ratio = 0, claimOver = 0;  // largest error/claim; largest claim/max(error, floor)
};

// Bakes one table and checks its corner texels; returns the worst ratios.
// strictReference: the rule in double must be sharp at every texel (ggx + smith-correlated's corner).
// tight: how many times max(error, float floor) a claim may be.
Worst checkTable(int ndf, int gaf, const Edge& e, int n, bool strictReference = true, double tight = 4) {
  KernelTable t = runner().hemisphere(ndf, gaf, n, n, false, weightOf(e));
  std::vector<std::pair<int, int>> texels;
  for (int j : cornerIndices(n))
    for (int i : cornerIndices(n)) texels.push_back({i, j});
  std::vector<std::future<std::pair<double, double>>> truth;
  for (auto [i, j] : texels) {
    double mu = static_cast<float>((i + 0.5) / n), r = static_cast<float>((j + 0.5) / n);
    truth.push_back(std::async(std::launch::async, [=] {
      double est = 0;
      double v = doubleRule(ndf, gaf, e, mu, r, &est);
      return std::make_pair(v, est);
    }));
    if (truth.size() % 2 == 0) truth[truth.size() - 2].wait();  // two threads
  }
  Worst w;
  // what float rounding alone leaves in a texel's claim: the floor a claim is never asked to beat
  const double floor = floatArithmeticError(1.0) + 1e-7;
  for (size_t q = 0; q < texels.size(); ++q) {
    auto [i, j] = texels[q];
    double mu = static_cast<float>((i + 0.5) / n), r = static_cast<float>((j + 0.5) / n);
    auto [want, est] = truth[q].get();
    size_t k = static_cast<size_t>(j) * n + i;
    double got = t.planes[1][k];
    double scale = 0;
    for (int p = 0; p < 3; ++p) scale = std::max(scale, std::fabs(static_cast<double>(t.planes[p][k])));
    // the bake's claim (host/tables/microfacet/microfacet.cpp): the estimate, the Fresnel-weighted float model
    // and the float term next to a kink
    double claim =
        t.err[k] + floatArithmeticError(scale, hemiFloatModel(ndf, gaf, true)) + fresnelKinkFloat(e.model, e.x, mu, r);
    double err = rel(got, want);
    EXPECT_TRUE(std::isfinite(got)) << e.name << " n=" << n << " mu=" << mu << " r=" << r;
    // Where the rule in double is itself uncertain by more than a twentieth of the claim (its
    // estimate: blinn-phong, the gaussian and their -exact GAFs at grazing texels), the device is
    // held to claim + that estimate, and the claim's tightness is not judged against it.
    const bool sharp = est < 0.05 * claim;
    if (strictReference)
      EXPECT_TRUE(sharp) << e.name << ": the double rule's own estimate " << est << " must be far below the claim "
                         << claim;
    EXPECT_LE(err, claim + (sharp ? 0.0 : est))
        << e.name << " n=" << n << " mu=" << mu << " r=" << r << " device " << got << " double " << want;
    if (sharp) EXPECT_LE(claim, tight * std::max(err, floor)) << e.name << " n=" << n << " mu=" << mu << " r=" << r;
    w.ratio = std::max(w.ratio, err / claim);
    w.claimOver = std::max(w.claimOver, claim / std::max(err, floor));
  }
  return w;
}

TEST(FresnelEdge, StiffCornerWithinItsClaim) {
  for (const Edge& e : edges())
    for (int n : {32, 64}) {
      Worst w = checkTable(NDF_GGX, GAF_SMITH_CORRELATED, e, n);
      std::printf("%-30s %3d^2: largest error/claim %.2f, claim/max(error, float floor) %.2f\n", e.name.c_str(), n,
                  w.ratio, w.claimOver);
    }
}

// The two edges the sweep found at 128^2, on a pair where each had been over its claim (eta = 0.2
// next to its critical cosine: ggx + smith-correlated 1.72 times; f82-tint at tint 0, grazing:
// beckmann + none), in the default run: every corner texel within its claim (the kink's float term
// and the Fresnel-weighted float model, tables/error_model.h). The kink's term is sized on the
// largest error over the 38 pairs (3.2e-6); ggx + smith-correlated's is 1.1e-6 there, so its claims
// reach 7.5 times the error: held to 8 times here (docs/accuracy.md, "The whole sweep"), 4 for F82.
// tools/bite.sh fresnel-kink-claim and fresnel-float-model remove each and see this fail.
TEST(FresnelEdge, TheSweepsEdgesHoldAt128) {
  const std::vector<Edge> all = edges();
  auto named = [&](const std::string& n) {
    for (const Edge& e : all)
      if (e.name == n) return e;
    ADD_FAILURE() << "no edge " << n;
    return all.front();
  };
  Worst tir = checkTable(NDF_GGX, GAF_SMITH_CORRELATED, named("dielectric eta=0.2"), 128, true, 8);
  Worst f82 = checkTable(NDF_BECKMANN, GAF_NONE, named("f82-tint F0=0.04 tint=0"), 128, false);
  std::printf(
      "128^2: eta 0.2 largest error/claim %.2f (claim/max(error, floor) %.2f); f82-tint tint 0 on beckmann + none "
      "%.2f (%.2f)\n",
      tir.ratio, tir.claimOver, f82.ratio, f82.claimOver);
}

// The corner texels where the independent reference is quick (see the top of this file), against
// it: value within the device's claim.
TEST(FresnelEdge, StiffCornerMatchesReference) {
  const int ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED, n = 32;
  for (const Edge& e : edges()) {
    bool slowRef = (e.model == FRESNEL_DIELECTRIC || e.model == FRESNEL_SCHLICK_TIR || e.model == FRESNEL_CONDUCTOR) &&
                   e.x < 1 && e.x > 0.99;
    std::vector<std::pair<int, int>> texels = {{0, 1}, {1, 0}, {3, 3}, {n - 1, n - 1}, {0, n - 1}, {n - 1, 0}};
    if (slowRef) texels = {{n - 1, n - 1}, {n - 1, 0}};
    KernelTable t = runner().hemisphere(ndf, gaf, n, n, false, weightOf(e));
    reference::Weight w{reference::Weight::Fresnel, {e.model, e.x, e.y}};
    for (auto [i, j] : texels) {
      double mu = static_cast<float>((i + 0.5) / n), r = static_cast<float>((j + 0.5) / n);
      double want =
          testing_ref::cached1(testing_ref::keyOf("albedo " + ndfNames()[ndf] + " " + gafNames()[gaf] + " fresnel-edge",
                                                  {r, mu, double(e.model), e.x, e.y}),
                               [&] { return reference::albedo(ndf, gaf, r, mu, w).b; });
      size_t k = static_cast<size_t>(j) * n + i;
      double scale = 0;
      for (int p = 0; p < 3; ++p) scale = std::max(scale, std::fabs(static_cast<double>(t.planes[p][k])));
      EXPECT_LE(rel(t.planes[1][k], want), t.err[k] + floatArithmeticError(scale, hemiFloatModel(ndf, gaf, true)) +
                                               fresnelKinkFloat(e.model, e.x, mu, r))
          << e.name << " mu=" << mu << " r=" << r << " device " << t.planes[1][k] << " reference " << want;
    }
  }
}

// The wider sweep: every NDF/GAF pair of the microfacet family, 32^2, 64^2 and 128^2 (17 minutes on
// two cores): `ctest -L sweep` (tests/CMakeLists.txt). At 128^2 dielectric eta = 0.2 next to its
// critical cosine and f82-tint at tint 0 at grazing views fail their claims (docs/accuracy.md,
// "The whole sweep, and the edge it found").
TEST(FresnelEdge, DISABLED_EveryPairEverySize) {
  for (int ndf : {NDF_GGX, NDF_BECKMANN, NDF_BLINN_PHONG, NDF_GAUSSIAN})
    for (int gaf = 0; gaf < static_cast<int>(gafNames().size()); ++gaf) {
      if (!pairSupported(ndf, gaf)) continue;
      for (const Edge& e : edges())
        for (int n : {32, 64, 128}) {
          Worst w = checkTable(ndf, gaf, e, n, false);
          std::printf("%s+%s %-30s %3d^2: largest error/claim %.2f, claim/max(error, floor) %.2f\n",
                      ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), e.name.c_str(), n, w.ratio, w.claimOver);
        }
    }
}

}  // namespace
