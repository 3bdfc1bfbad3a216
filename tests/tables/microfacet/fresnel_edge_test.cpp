// The Fresnel albedo at its stiff corner: every Fresnel model at its extreme parameters (eta within
// 1e-6 to 1e-2 of 1 on both sides, eta 0.2 and 5, a conductor with k -> 0 and k = 10, F82-tint's
// tint 0 and 1), baked on the device, checked texel by texel where a narrow lobe meets F's steep
// edge: the first and last four mu columns and r rows of 32^2 and 64^2 tables (128^2, 256^2 and every
// pair in the sweep below, ctest's FresnelSweep.EveryPairEverySize behind the label `sweep`).
//
// Each texel is checked against the independent reference (host/reference: adaptive in the half
// vector's angles, F from the complex amplitudes at eta in double, F's square-root end at the
// critical cosine integrated in the distance to it; 1e-11 per integral, a few milliseconds a
// texel): the device's value must be within its claim (its estimate + the float arithmetic, as
// the bake claims it), and the claim at most `tight` times that error or the float floor,
// whichever is larger.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/models.h"
#include "doc_figures.h"
#include "reference/reference.h"
#include "reference_cache.h"
#include "tables/error_model.h"
#include "tables/ladder.h"
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

// The reference's Fresnel albedo (b) at every texel of `texels`, on two threads.
std::vector<double> referenceValues(int ndf, int gaf, const Edge& e, int n,
                                    const std::vector<std::pair<int, int>>& texels) {
  std::vector<double> out(texels.size());
  ladder::onTwoThreads(texels.size(), [&](size_t q) {
    auto [i, j] = texels[q];
    double mu = static_cast<float>((i + 0.5) / n), r = static_cast<float>((j + 0.5) / n);
    out[q] = reference::albedo(ndf, gaf, r, mu, {reference::Weight::Fresnel, {e.model, e.x, e.y}}).b;
  });
  return out;
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

// The largest of each over several tables, and where each was.
struct WorstOf {
  Worst all;
  std::string ratioAt, overAt;
  void add(const Worst& w, const std::string& at) {
    if (w.ratio > all.ratio) all.ratio = w.ratio, ratioAt = at;
    if (w.claimOver > all.claimOver) all.claimOver = w.claimOver, overAt = at;
  }
};

// A corner texel's three planes and its estimate, as the bake's table holds them.
struct Texel {
  float a = 0, b = 0, e = 0, err = 0;
};

// The corner texels of an n x n table, keyed (i, j): the whole table baked (whole = true), or only
// its four 4 x 4 corner blocks, one hemisphereRange launch each. Each texel is computed on its own
// (kernels/bake.cl), and a block's texel centres are the table's to the bit (4/n, (i + 0.5) and
// n - 4 are exact in float), so the blocks hold the table's bits: FresnelEdge.CornerBlocksAreTheTable
// checks that. The blocks take 64 texels a table, where 256^2 bakes 65536 (1.5 s a table).
std::map<std::pair<int, int>, Texel> cornerTexels(int ndf, int gaf, const HemiWeight& w, int n, bool whole) {
  std::map<std::pair<int, int>, Texel> out;
  if (whole) {
    KernelTable t = runner().hemisphere(ndf, gaf, n, n, false, w);
    for (int j : cornerIndices(n))
      for (int i : cornerIndices(n)) {
        size_t k = static_cast<size_t>(j) * n + i;
        out[{i, j}] = {t.planes[0][k], t.planes[1][k], t.planes[2][k], t.err[k]};
      }
    return out;
  }
  for (int bj : {0, n - 4})
    for (int bi : {0, n - 4}) {
      const float lo = static_cast<float>(bi) / n, hi = static_cast<float>(bi + 4) / n;
      const float rlo = static_cast<float>(bj) / n, rhi = static_cast<float>(bj + 4) / n;
      KernelTable t = runner().hemisphereRange(ndf, gaf, 4, 4, lo, hi, rlo, rhi, false, w);
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          size_t k = static_cast<size_t>(j) * 4 + i;
          out[{bi + i, bj + j}] = {t.planes[0][k], t.planes[1][k], t.planes[2][k], t.err[k]};
        }
    }
  return out;
}

// A texel's claim as the bake makes it (host/tables/microfacet/microfacet.cpp): the estimate and the
// Fresnel-weighted float model.
double claimOf(const Texel& t, int ndf, int gaf, int fresnelModel) {
  const double scale = std::max({std::fabs(double(t.a)), std::fabs(double(t.b)), std::fabs(double(t.e))});
  return t.err + weightedFloatError(t.b, t.e, scale, ndf, gaf, weightCancels(fresnelModel));
}

// Checks one table's corner texels against the reference; returns the worst ratios.
// tight: how many times max(error, float floor) a claim may be. whole: bake the whole table, else
// its corner blocks (cornerTexels).
Worst checkTable(int ndf, int gaf, const Edge& e, int n, double tight = 4, bool whole = true) {
  const auto corner = cornerTexels(ndf, gaf, weightOf(e), n, whole);
  std::vector<std::pair<int, int>> texels;
  for (int j : cornerIndices(n))
    for (int i : cornerIndices(n)) texels.push_back({i, j});
  const std::vector<double> truth = referenceValues(ndf, gaf, e, n, texels);
  Worst w;
  // what float rounding alone leaves in a texel's claim: the floor a claim is never asked to beat
  const double floor = floatArithmeticError(1.0) + 1e-7;
  for (size_t q = 0; q < texels.size(); ++q) {
    auto [i, j] = texels[q];
    double mu = static_cast<float>((i + 0.5) / n), r = static_cast<float>((j + 0.5) / n);
    double want = truth[q];
    const Texel& t = corner.at(texels[q]);
    double got = t.b;
    double claim = claimOf(t, ndf, gaf, e.model);
    double err = rel(got, want);
    EXPECT_TRUE(std::isfinite(got)) << e.name << " n=" << n << " mu=" << mu << " r=" << r;
    EXPECT_LE(err, claim) << ndfNames()[ndf] << "+" << gafNames()[gaf] << " " << e.name << " n=" << n << " mu=" << mu
                          << " r=" << r << " device " << got << " reference " << want;
    EXPECT_LE(claim, tight * std::max(err, floor))
        << ndfNames()[ndf] << "+" << gafNames()[gaf] << " " << e.name << " n=" << n << " mu=" << mu << " r=" << r;
    if (std::getenv("BRDFBAKE_SWEEP_TEXELS"))
      std::printf("texel %s+%s %s n=%d mu=%.6f r=%.6f A=%.6g B=%.6g E=%.6g error/u=%.2f claim/u=%.2f\n",
                  ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), e.name.c_str(), n, mu, r, t.a, t.b, t.e,
                  err / kUnitRoundoff, claim / kUnitRoundoff);
    w.ratio = std::max(w.ratio, err / claim);
    w.claimOver = std::max(w.claimOver, claim / std::max(err, floor));
  }
  return w;
}

// The blocks hold the whole table's bits at every corner texel.
void expectBlocksAreTheTable(int ndf, int gaf, const HemiWeight& w, int n) {
  const auto whole = cornerTexels(ndf, gaf, w, n, true);
  const auto blocks = cornerTexels(ndf, gaf, w, n, false);
  ASSERT_EQ(whole.size(), 64u);
  ASSERT_EQ(blocks.size(), 64u);
  for (const auto& [ij, t] : whole) {
    const Texel& b = blocks.at(ij);
    EXPECT_TRUE(t.a == b.a && t.b == b.b && t.e == b.e && t.err == b.err)
        << "n=" << n << " texel (" << ij.first << ", " << ij.second << "): table " << t.b << " block " << b.b;
  }
}

// The sweep's 256^2 tables are their corner blocks: the blocks hold the whole table's bits, for a
// Fresnel weight with a kink and for the split sum (the sweep checks 256^2 itself on the default pair).
TEST(FresnelEdge, CornerBlocksAreTheTable) {
  for (const HemiWeight& w : {fresnelWeight(FRESNEL_DIELECTRIC, 0.2, 0), HemiWeight{}})
    for (int n : {32, 64}) expectBlocksAreTheTable(NDF_BECKMANN, GAF_SMITH, w, n);
}

// Why the host passes z beside eta (docs/accuracy.md, "The stiff corner"): at eta = 0.9999 the
// Fresnel term depends on eta only through eta^2 - 1, which float(eta) holds to ~2e-5. At mu = 1/64,
// r = 3/64 of a 32^2 albedo table the reference at float(eta) is off the reference at eta by
// hundreds of the texel's claims; the device with z bakes the latter within its claim, the device
// with z = 0 (eta's float alone) the former.
TEST(FresnelEdge, FloatEtaAloneMissesByHundredsOfClaims) {
  const int ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED, n = 32;
  const Edge e{"dielectric eta=0.9999", FRESNEL_DIELECTRIC, 0.9999, 0};
  const Edge asFloat{"dielectric eta=float(0.9999)", FRESNEL_DIELECTRIC, static_cast<float>(0.9999), 0};
  const std::pair<int, int> texel{0, 1};  // mu = 1/64, r = 3/64
  const double want = referenceValues(ndf, gaf, e, n, {texel})[0];
  const double atFloat = referenceValues(ndf, gaf, asFloat, n, {texel})[0];
  HemiWeight withoutZ = weightOf(e);
  EXPECT_NE(withoutZ.z, 0.0f);  // and the checks below show what z = 0 does
  withoutZ.z = 0;
  const Texel with = cornerTexels(ndf, gaf, weightOf(e), n, true).at(texel);
  const Texel without = cornerTexels(ndf, gaf, withoutZ, n, true).at(texel);
  const double claim = claimOf(with, ndf, gaf, e.model), claimWithout = claimOf(without, ndf, gaf, e.model);
  EXPECT_LE(rel(with.b, want), claim) << "device " << with.b << " reference " << want;
  EXPECT_GT(rel(without.b, want), 100 * claimWithout) << "device without z " << without.b;
  EXPECT_LE(rel(without.b, atFloat), claimWithout) << "device without z " << without.b << " at float " << atFloat;
  std::string said;  // docs/accuracy.md quotes it
  testing_docs::say(said,
                    "eta 0.9999, mu 1/64, r 3/64 of a 32^2 albedo table: reference %.9f, at float(eta) %.7f, %.0f "
                    "times the texel's claim (%.2e) away; the device with z %.7f, without z %.7f\n",
                    want, atFloat, rel(atFloat, want) / claim, claim, with.b, without.b);
  testing_docs::expectPagesQuote(said);
}

TEST(FresnelEdge, StiffCornerWithinItsClaim) {
  WorstOf worst;
  for (const Edge& e : edges())
    for (int n : {32, 64}) {
      Worst w = checkTable(NDF_GGX, GAF_SMITH_CORRELATED, e, n);
      std::printf("%-30s %3d^2: largest error/claim %.2f, claim/max(error, float floor) %.2f\n", e.name.c_str(), n,
                  w.ratio, w.claimOver);
      worst.add(w, e.name + " at " + std::to_string(n) + "^2");
    }
  std::printf("every edge: largest error/claim %.2f (%s), largest claim/max(error, float floor) %.2f (%s)\n",
              worst.all.ratio, worst.ratioAt.c_str(), worst.all.claimOver, worst.overAt.c_str());
}

// The edges the sweep found, each on a pair where it had been over its claim, in the default run:
// at 128^2 eta = 0.2 next to its critical cosine (ggx + smith-correlated, 1.72 times) and f82-tint
// at tint 0 at grazing views (beckmann + none); at 256^2 (its corner blocks) f82-tint at tint 0 on
// gaussian + none, where E = int H reaches 154 (1.72 times). Every corner texel within its claim, and
// every claim within 4 times max(error, float floor): the kernels' o.h - ck from the node's geometry
// next to the kink (kernels/integrate/integrand.h hemi_kink_offset), the Fresnel-weighted float model
// and F82's share of E (tables/error_model.h). tools/bite.sh fresnel-kink-offset, fresnel-float-model
// and f82-share-of-e remove each and see this fail.
TEST(FresnelEdge, TheSweepsEdgesHold) {
  const std::vector<Edge> all = edges();
  auto named = [&](const std::string& n) {
    for (const Edge& e : all)
      if (e.name == n) return e;
    ADD_FAILURE() << "no edge " << n;
    return all.front();
  };
  Worst tir = checkTable(NDF_GGX, GAF_SMITH_CORRELATED, named("dielectric eta=0.2"), 128);
  Worst f82 = checkTable(NDF_BECKMANN, GAF_NONE, named("f82-tint F0=0.04 tint=0"), 128);
  Worst f82e = checkTable(NDF_GAUSSIAN, GAF_NONE, named("f82-tint F0=0.04 tint=0"), 256, 4, false);
  std::printf(
      "128^2: eta 0.2 largest error/claim %.2f (claim/max(error, floor) %.2f); f82-tint tint 0 on beckmann + none "
      "%.2f (%.2f); 256^2: f82-tint tint 0 on gaussian + none %.2f (%.2f)\n",
      tir.ratio, tir.claimOver, f82.ratio, f82.claimOver, f82e.ratio, f82e.claimOver);
}

// The average albedo (albedo-avg with --fresnel) at the stiff corner: the Fresnels with a critical
// cosine or a graded layer next to eta = 1, at the first two and last two r of a 32-entry table,
// against the reference's average (adaptive in mu, split at the critical cosine and at lobe widths
// around it, over the albedo above; 5 to 12 s a value, kept in tests/data/reference_values.txt).
TEST(FresnelEdge, AverageAlbedoAtTheStiffCorner) {
  const int ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED, n = 32;
  // what float rounding alone leaves in an entry's claim: the average's float model at E_avg = 1 (the
  // nodes' weighted bounds, 18 u), plus checkTable's 1e-7
  const double floor = avgFloatArithmeticError(1.0, ndf, gaf, true) + 1e-7;
  double worst = 0, over = 0;
  for (const Edge& e : edges()) {
    if (e.name != "dielectric eta=1-0.000100" && e.name != "dielectric eta=1+0.000100" &&
        e.name != "dielectric eta=0.2" && e.name != "schlick-tir eta=0.9999")
      continue;
    KernelTable t = runner().albedoAvg(ndf, gaf, n, false, weightOf(e));
    reference::Weight w{reference::Weight::Fresnel, {e.model, e.x, e.y}};
    for (int j : {0, 1, n - 2, n - 1}) {
      double r = static_cast<float>((j + 0.5) / n);
      double want = testing_ref::cached1(
          testing_ref::keyOf("albedoAvg " + ndfNames()[ndf] + " " + gafNames()[gaf] + " fresnel-edge",
                             {r, double(e.model), e.x, e.y}),
          [&] { return reference::albedoAvg(ndf, gaf, r, w); });
      double err = rel(t.planes[0][j], want);
      double claim = t.err[j] + avgFloatArithmeticError(t.planes[0][j], ndf, gaf, true);
      EXPECT_LE(err, claim) << e.name << " r=" << r << " device " << t.planes[0][j] << " reference " << want;
      EXPECT_LE(claim, 4 * std::max(err, floor)) << e.name << " r=" << r;
      worst = std::max(worst, err / claim);
      over = std::max(over, claim / std::max(err, floor));
    }
  }
  std::printf("albedo-avg at the stiff corner: largest error/claim %.2f, claim/max(error, float floor) %.2f\n", worst,
              over);
}

// The wider sweep: every NDF/GAF pair of the microfacet family (52) at 32^2, 64^2, 128^2 and
// 256^2 (the last as its corner blocks, cornerTexels; on the default pair also whole, and the two
// compared), each corner texel against the reference: `ctest -L sweep` (tests/CMakeLists.txt).
// Every claim is held to 4 times max(error, float floor).
// BRDFBAKE_SWEEP_PAIRS=NDF+GAF,... runs those pairs alone (a slice to rerun after a change),
// BRDFBAKE_SWEEP_EDGES=NAME,... the edges whose names contain one of those words ("eta=0.2"), and
// BRDFBAKE_SWEEP_SIZES=N,... those table sizes;
// BRDFBAKE_SWEEP_TEXELS=1 prints every corner texel's A, B, E, error and claim (in u = 2^-24).
// A whole run ends with the sweep's two maxima, which docs/accuracy.md quotes and this test checks
// there; a slice's maxima are its own and are not checked.
TEST(FresnelEdge, DISABLED_EveryPairEverySize) {
  const char* only = std::getenv("BRDFBAKE_SWEEP_PAIRS");
  const std::string pairs = only ? "," + std::string(only) + "," : "";
  auto listed = [](const char* var, const std::string& item, bool contains) {
    const char* v = std::getenv(var);
    if (!v) return true;
    std::string list = v;
    for (size_t at = 0; at <= list.size();) {
      const size_t end = std::min(list.find(',', at), list.size());
      const std::string word = list.substr(at, end - at);
      if (!word.empty() && (contains ? item.find(word) != std::string::npos : item == word)) return true;
      at = end + 1;
    }
    return false;
  };
  WorstOf worst;
  for (int ndf : {NDF_GGX, NDF_BECKMANN, NDF_BLINN_PHONG, NDF_GAUSSIAN})
    for (int gaf = 0; gaf < static_cast<int>(gafNames().size()); ++gaf) {
      if (!pairSupported(ndf, gaf)) continue;
      if (only && pairs.find("," + ndfNames()[ndf] + "+" + gafNames()[gaf] + ",") == std::string::npos) continue;
      const bool defaultPair = ndf == NDF_GGX && gaf == GAF_SMITH_CORRELATED;
      for (const Edge& e : edges())
        for (int n : {32, 64, 128, 256}) {
          if (!listed("BRDFBAKE_SWEEP_EDGES", e.name, true) ||
              !listed("BRDFBAKE_SWEEP_SIZES", std::to_string(n), false))
            continue;
          if (n == 256 && defaultPair) expectBlocksAreTheTable(ndf, gaf, weightOf(e), n);
          Worst w = checkTable(ndf, gaf, e, n, 4, n < 256);
          std::printf("%s+%s %-30s %3d^2: largest error/claim %.2f, claim/max(error, floor) %.2f\n",
                      ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), e.name.c_str(), n, w.ratio, w.claimOver);
          worst.add(w, ndfNames()[ndf] + "+" + gafNames()[gaf] + " " + e.name + " " + std::to_string(n) + "^2");
        }
    }
  std::string said;
  testing_docs::say(said, "the whole sweep: largest error/claim %.2f (%s), largest claim/max(error, floor) %.2f (%s)\n",
                    worst.all.ratio, worst.ratioAt.c_str(), worst.all.claimOver, worst.overAt.c_str());
  if (!only && !std::getenv("BRDFBAKE_SWEEP_EDGES") && !std::getenv("BRDFBAKE_SWEEP_SIZES"))
    testing_docs::expectPagesQuote(said);
}

}  // namespace
